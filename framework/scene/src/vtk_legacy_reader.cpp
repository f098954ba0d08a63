// Legacy VTK (.vtk) POLYDATA, ASCII or BINARY (big-endian): POINTS, VERTICES,
// LINES, POLYGONS, TRIANGLE_STRIPS (classic "n size" layout and the 5.1
// OFFSETS/CONNECTIVITY layout), POINT_DATA/CELL_DATA with SCALARS, VECTORS,
// NORMALS, TEXTURE_COORDINATES, TENSORS, COLOR_SCALARS and FIELD arrays.
// Binary triangle meshes are read by vtk_legacy/legacy_triangles.h, straight
// into the surface's arrays; this general reader takes every other file, and
// every file that one finds wrong, so that it alone words the errors.
#include <darkroom/data/formats/number_text.h>
#include <darkroom/data/formats/binary_values.h>
#include "poly_mesh.h"
#include "vtk_legacy/legacy_triangles.h"
#include "vtk_legacy/legacy_types.h"
#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/scene/mesh_readers.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <optional>

namespace darkroom {
namespace {

using mesh::ValueType;
using vtk_legacy::legacyType;

class LegacyReader {
public:
    LegacyReader(const std::string& path, std::string_view data) : path_(path), cur_(path, data) {}

    mesh::PolyMesh read() {
        readHeader();
        m_.source = path_;
        while (!cur_.atEnd()) {
            line_ = cur_.line();
            const auto t = mesh::splitBlanks(cur_.restOfLine());
            if (t.empty()) continue;
            keyword(t);
        }
        // VTK numbers cells vertices first, then lines, polygons, strips.
        std::uint32_t id = 0;
        for (mesh::CellList* l : {&m_.vertices, &m_.lines, &m_.polygons, &m_.strips})
            for (auto& c : l->cellIds) c = id++;
        m_.cellCount = id;
        return std::move(m_);
    }

private:
    [[noreturn]] void failLine(const std::string& what) const {
        throw Error(path_ + ":" + std::to_string(line_) + ": " + what);
    }

    void readHeader() {
        const std::string_view first = cur_.restOfLine();
        if (first.substr(0, 5) != "# vtk") throw Error(path_ + ":1: " + "missing VTK header: expected '# vtk DataFile Version x.x' on the first line");
        cur_.restOfLine();  // title
        line_ = cur_.line();
        const auto fmt = mesh::splitBlanks(cur_.restOfLine());
        if (fmt.size() == 1 && fmt[0] == "ASCII") binary_ = false;
        else if (fmt.size() == 1 && fmt[0] == "BINARY") binary_ = true;
        else failLine("expected ASCII or BINARY on the third line");
        while (!cur_.atEnd()) {
            line_ = cur_.line();
            const auto t = mesh::splitBlanks(cur_.restOfLine());
            if (t.empty()) continue;
            if (t.size() != 2 || t[0] != "DATASET") failLine("expected 'DATASET POLYDATA'");
            if (t[1] != "POLYDATA")
                failLine("unsupported dataset type '" + std::string(t[1]) + "', only POLYDATA is read (convert with ParaView's Extract Surface)");
            return;
        }
        cur_.fail("unexpected end of file, expected 'DATASET POLYDATA'");
    }

    std::size_t count(std::string_view tok, const char* what) const {
        long long n = 0;
        if (!mesh::parseInteger(tok, n) || n < 0)
            failLine(std::string("expected ") + what + " (a non-negative integer), got '" + std::string(tok) + "'");
        // Every counted thing takes at least a byte of the rest of the file;
        // this also keeps products like count x components from overflowing.
        if (std::size_t(n) > cur_.remaining() + 1)
            failLine(std::string(what) + " " + std::string(tok) + " is larger than the rest of the file can hold (truncated?)");
        return std::size_t(n);
    }

    ValueType type(std::string_view tok) const {
        const auto t = legacyType(tok);
        if (!t) failLine("unknown data type '" + std::string(tok) + "' (expected float, double, int, unsigned_char, ...)");
        return *t;
    }

    // n values of type t: tokens in ASCII files, big-endian bytes in BINARY ones.
    std::vector<double> values(std::size_t n, ValueType t, const std::string& what) {
        // Each value needs at least 2 characters (ASCII) or its size (binary):
        // refuse impossible counts before allocating for them.
        const std::size_t least = binary_ ? mesh::sizeOf(t) : 2;
        if (n > (cur_.remaining() + 1) / least)
            throw Error(path_ + ": element " + what + " (after line " + std::to_string(line_) + "): file ends early (truncated), expected " +
                        std::to_string(n) + " values");
        std::vector<double> out(n);
        if (!binary_) {
            for (auto& v : out) v = cur_.number("a number in " + what);
            return out;
        }
        const std::size_t sz = mesh::sizeOf(t);
        if (n > 0 && SIZE_MAX / n < sz) failLine(what + ": value count too large");
        const char* p = cur_.take(n * sz);
        if (!p)
            throw Error(path_ + ": element " + what + " (after line " + std::to_string(line_) + "): file ends early (truncated), expected " +
                        std::to_string(n * sz) + " bytes of binary data");
        for (std::size_t i = 0; i < n; ++i) out[i] = mesh::loadValue(t, p + i * sz, true);
        return out;
    }

    std::uint32_t pointIndex(double v, const std::string& what) const {
        if (!(v >= 0 && v < double(m_.pointCount())) || v != std::floor(v))
            failLine(what + ": point index " + mesh::numberText(v) + " out of range, expected 0 to " +
                     std::to_string(static_cast<long long>(m_.pointCount()) - 1));
        return static_cast<std::uint32_t>(v);
    }

    void cells(const std::vector<std::string_view>& t, mesh::CellList& list) {
        const std::string what(t[0]);
        if (t.size() != 3) failLine("expected '" + what + " <cells> <size>'");
        const std::size_t a = count(t[1], "a cell count"), b = count(t[2], "a size");
        const auto save = cur_.mark();
        const auto next = mesh::splitBlanks(cur_.restOfLine());
        if (!next.empty() && next[0] == "OFFSETS") {
            // VTK 5.1 layout: a offsets (a = cells + 1), then b connectivity entries.
            line_ = cur_.line() - 1;
            if (next.size() != 2 || a == 0) failLine("expected 'OFFSETS <type>' with at least one offset");
            const auto off = values(a, type(next[1]), what + " OFFSETS");
            cur_.atEnd();  // step over the newline after the last offset
            line_ = cur_.line();
            const auto conn_h = mesh::splitBlanks(cur_.restOfLine());
            if (conn_h.size() != 2 || conn_h[0] != "CONNECTIVITY") failLine("expected 'CONNECTIVITY <type>' after OFFSETS");
            const auto conn = values(b, type(conn_h[1]), what + " CONNECTIVITY");
            for (std::size_t c = 0; c + 1 < a; ++c) {
                if (!(off[c] >= 0 && off[c] <= off[c + 1] && off[c + 1] <= double(b)))
                    failLine(what + ": offsets must increase from 0 to " + std::to_string(b));
                for (auto k = std::size_t(off[c]); k < std::size_t(off[c + 1]); ++k)
                    list.connectivity.push_back(pointIndex(conn[k], what));
                list.close(0);
            }
            return;
        }
        cur_.reset(save);
        // Classic layout: b integers, each cell as its size followed by its points.
        const auto v = values(b, ValueType::Int32, what);
        std::size_t k = 0;
        for (std::size_t c = 0; c < a; ++c) {
            if (k >= v.size()) failLine(what + ": cell " + std::to_string(c) + " lies beyond the declared size " + std::to_string(b));
            const double n = v[k++];
            if (!(n >= 0) || n > double(v.size() - k))
                failLine(what + ": cell " + std::to_string(c) + " has " + mesh::numberText(n) +
                         " points, more than the declared size " + std::to_string(b) + " holds");
            for (std::size_t j = 0; j < std::size_t(n); ++j) list.connectivity.push_back(pointIndex(v[k++], what));
            list.close(0);
        }
    }

    void addArray(std::string name, int components, std::vector<double> v) {
        mesh::DataArray a{std::move(name), components, std::vector<float>(v.begin(), v.end())};
        if (section_ == Section::Point) m_.pointData.push_back(std::move(a));
        else if (section_ == Section::Cell) m_.cellData.push_back(std::move(a));
        // FIELD data of the whole dataset has no geometry to follow; dropped.
    }

    std::size_t tuples() const { return section_ == Section::None ? 0 : sectionCount_; }

    void keyword(const std::vector<std::string_view>& t) {
        const std::string_view k = t[0];
        if (k == "POINTS") {
            if (t.size() != 3) failLine("expected 'POINTS <count> <type>'");
            const auto v = values(count(t[1], "a point count") * 3, type(t[2]), "POINTS");
            m_.points.assign(v.begin(), v.end());
        } else if (k == "VERTICES") {
            cells(t, m_.vertices);
        } else if (k == "LINES") {
            cells(t, m_.lines);
        } else if (k == "POLYGONS") {
            cells(t, m_.polygons);
        } else if (k == "TRIANGLE_STRIPS") {
            cells(t, m_.strips);
        } else if (k == "POINT_DATA" || k == "CELL_DATA") {
            if (t.size() != 2) failLine("expected '" + std::string(k) + " <count>'");
            section_ = k == "POINT_DATA" ? Section::Point : Section::Cell;
            sectionCount_ = count(t[1], "a count");
        } else if (k == "SCALARS") {
            if (t.size() < 3 || t.size() > 4) failLine("expected 'SCALARS <name> <type> [components]'");
            const int nc = t.size() == 4 ? int(count(t[3], "a component count")) : 1;
            if (nc < 1 || nc > 4) failLine("SCALARS components must be 1 to 4");
            const ValueType vt = type(t[2]);
            // The LOOKUP_TABLE line is optional in practice; look before reading values.
            const auto save = cur_.mark();
            const auto next = mesh::splitBlanks(cur_.restOfLine());
            if (next.empty() || next[0] != "LOOKUP_TABLE") cur_.reset(save);
            addArray(std::string(t[1]), nc, values(tuples() * std::size_t(nc), vt, "SCALARS " + std::string(t[1])));
        } else if (k == "VECTORS" || k == "NORMALS") {
            if (t.size() != 3) failLine("expected '" + std::string(k) + " <name> <type>'");
            addArray(std::string(t[1]), 3, values(tuples() * 3, type(t[2]), std::string(k) + " " + std::string(t[1])));
        } else if (k == "TENSORS") {
            if (t.size() != 3) failLine("expected 'TENSORS <name> <type>'");
            addArray(std::string(t[1]), 9, values(tuples() * 9, type(t[2]), "TENSORS " + std::string(t[1])));
        } else if (k == "TEXTURE_COORDINATES") {
            if (t.size() != 4) failLine("expected 'TEXTURE_COORDINATES <name> <dim> <type>'");
            const int nc = int(count(t[2], "a dimension"));
            addArray(std::string(t[1]), nc, values(tuples() * std::size_t(nc), type(t[3]), "TEXTURE_COORDINATES"));
        } else if (k == "COLOR_SCALARS") {
            if (t.size() != 3) failLine("expected 'COLOR_SCALARS <name> <components>'");
            const int nc = int(count(t[2], "a component count"));
            // Floats in [0,1] in ASCII files, bytes in BINARY ones.
            auto v = values(tuples() * std::size_t(nc), binary_ ? ValueType::UInt8 : ValueType::Float32, "COLOR_SCALARS");
            if (binary_)
                for (auto& x : v) x /= 255.0;
            addArray(std::string(t[1]), nc, std::move(v));
        } else if (k == "LOOKUP_TABLE") {
            if (t.size() != 3) failLine("expected 'LOOKUP_TABLE <name> <size>'");
            values(count(t[2], "a table size") * 4, binary_ ? ValueType::UInt8 : ValueType::Float32, "LOOKUP_TABLE");
        } else if (k == "FIELD") {
            if (t.size() != 3) failLine("expected 'FIELD <name> <arrays>'");
            const std::size_t n = count(t[2], "an array count");
            for (std::size_t i = 0; i < n; ++i) {
                if (cur_.atEnd()) cur_.fail("unexpected end of file, expected FIELD array " + std::to_string(i));
                line_ = cur_.line();
                const auto a = mesh::splitBlanks(cur_.restOfLine());
                if (a.size() != 4) failLine("expected '<array name> <components> <tuples> <type>' in FIELD");
                const std::size_t nc = count(a[1], "a component count"), nt = count(a[2], "a tuple count");
                auto v = values(nc * nt, type(a[3]), "FIELD array " + std::string(a[0]));
                if (section_ != Section::None && nt != sectionCount_)
                    failLine("FIELD array '" + std::string(a[0]) + "' has " + std::to_string(nt) + " tuples, expected " +
                             std::to_string(sectionCount_));
                if (nc >= 1) addArray(std::string(a[0]), int(nc), std::move(v));
                skipMetadata();
            }
        } else if (k == "METADATA") {
            skipMetadataBody();
        } else {
            failLine("unexpected keyword '" + std::string(k.substr(0, 40)) + "' in POLYDATA");
        }
        skipMetadata();
    }

    // VTK 8.2+ may follow an array with a METADATA block that ends at a blank line.
    void skipMetadata() {
        const auto save = cur_.mark();
        if (cur_.atEnd()) return;
        const auto t = mesh::splitBlanks(cur_.restOfLine());
        if (!t.empty() && t[0] == "METADATA") skipMetadataBody();
        else cur_.reset(save);
    }
    void skipMetadataBody() {
        while (cur_.position() < SIZE_MAX) {
            const auto save = cur_.mark();
            const auto l = cur_.restOfLine();
            if (mesh::splitBlanks(l).empty()) return;
            if (cur_.mark().pos == save.pos) return;  // end of file
        }
    }

    enum class Section { None, Point, Cell };
    std::string path_;
    mesh::TextCursor cur_;
    bool binary_ = false;
    int line_ = 1;
    Section section_ = Section::None;
    std::size_t sectionCount_ = 0;
    mesh::PolyMesh m_;
};

}  // namespace

std::vector<SceneObject> readVtkLegacy(const std::string& path) { return readVtkLegacy(path, VtkLegacyReadOptions{}); }

std::vector<SceneObject> readVtkLegacy(const std::string& path, const VtkLegacyReadOptions& options) {
    const std::string name = std::filesystem::path(path).stem().string();
    if (options.direct) {
        std::optional<SceneObject> surface =
            vtk_legacy::readTriangles(path, name, std::max<std::size_t>(options.windowBytes, 1));
        if (surface) {
            std::vector<SceneObject> out;
            out.push_back(std::move(*surface));
            return out;
        }
    }
    const std::string data = mesh::readWholeFile(path, "mesh");
    LegacyReader reader(path, data);
    return mesh::buildSceneObjects(reader.read(), name);
}

}  // namespace darkroom
