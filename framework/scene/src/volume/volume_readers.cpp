// Volumes from VTK XML files: UnstructuredGrid (.vtu) keeping every cell, and
// ImageData (.vti) as implicit voxels. The DataArray decoding is the mesh
// readers' (../vtk_data_array.h); only the dataset structure is read here.
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/data/formats/vtk_data_array.h>
#include <darkroom/data/formats/xml_document.h>
#include "cell_topology.h"

#include <darkroom/error.h>
#include <darkroom/scene/volume.h>

#include <cctype>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace darkroom {
namespace {

using mesh::XmlElement;

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

class VolumeReader {
public:
    VolumeReader(const std::string& path, std::vector<std::string>* warnings) : path_(path), warnings_(warnings) {}

    VolumeMesh read() {
        data_ = mesh::readWholeFile(path_, "volume");
        doc_ = mesh::parseVtkXml(data_, path_);
        const XmlElement& root = *doc_.root;
        if (root.name != "VTKFile") fail(root, "expected <VTKFile> as the root element, got <" + root.name + ">");
        const std::string type = root.attributeOr("type", "");
        enc_ = mesh::vtkXmlEncoding(doc_, path_);
        enc_.doc = &doc_;
        v_.source = path_;
        const XmlElement* dataset = root.child(type);
        if (type == "UnstructuredGrid" && dataset) unstructured(*dataset);
        else if (type == "ImageData" && dataset) image(*dataset);
        else if (!dataset && (type == "UnstructuredGrid" || type == "ImageData")) fail(root, "missing <" + type + ">");
        else fail(root, "dataset type '" + type + "' is not a volume (expected UnstructuredGrid or ImageData)");
        return std::move(v_);
    }

private:
    [[noreturn]] void fail(const XmlElement& e, const std::string& what) const {
        throw Error(path_ + ":" + std::to_string(e.line) + ": " + what);
    }

    mesh::VtkArray array(const XmlElement& e) const { return mesh::readVtkDataArray(e, enc_); }

    mesh::VtkArray named(const XmlElement& parent, const std::string& name) const {
        for (const auto& c : parent.children)
            if (c->name == "DataArray" && c->attributeOr("Name", "") == name) return array(*c);
        fail(parent, "<" + parent.name + "> lacks the DataArray '" + name + "'");
    }

    // Point or cell arrays of one piece, appended to `out` (pieces must agree).
    void arrays(const XmlElement* parent, std::size_t tuples, std::vector<VolumeArray>& out, bool first) const {
        std::size_t k = 0;
        if (parent)
            for (const auto& c : parent->children) {
                if (c->name != "DataArray") continue;
                const mesh::VtkArray a = array(*c);
                if (a.values.size() != tuples * std::size_t(a.components))
                    fail(*c, "DataArray '" + a.name + "' has " + std::to_string(a.values.size()) + " values, expected " +
                                 std::to_string(tuples) + " x " + std::to_string(a.components));
                if (first) {
                    out.push_back({a.name, a.components, std::vector<float>(a.values.begin(), a.values.end())});
                } else {
                    if (k >= out.size() || out[k].name != a.name || out[k].components != a.components)
                        fail(*c, "pieces carry different data arrays ('" + a.name + "')");
                    out[k].values.insert(out[k].values.end(), a.values.begin(), a.values.end());
                }
                ++k;
            }
        if (!first && k != out.size()) fail(parent ? *parent : *doc_.root, "pieces carry different data arrays");
    }

    void unstructured(const XmlElement& dataset) {
        bool first = true;
        for (const auto& piece : dataset.children) {
            if (piece->name != "Piece") continue;
            const std::size_t np = mesh::vtkCountAttribute(*piece, path_, "NumberOfPoints");
            const std::size_t nc = mesh::vtkCountAttribute(*piece, path_, "NumberOfCells");
            const std::size_t base = v_.points.size() / 3;
            if (np > 0) {
                const XmlElement* pts = piece->child("Points");
                if (!pts) fail(*piece, "missing <Points>");
                const XmlElement* arr = pts->child("DataArray");
                if (!arr) fail(*pts, "<Points> lacks its DataArray");
                const mesh::VtkArray p = array(*arr);
                if (p.components != 3 || p.values.size() != np * 3)
                    fail(*arr, "points have " + std::to_string(p.values.size()) + " values in " +
                                   std::to_string(p.components) + " components, expected " + std::to_string(np) + " x 3");
                v_.points.insert(v_.points.end(), p.values.begin(), p.values.end());
            }
            if (nc > 0) cells(*piece, nc, base, np);
            arrays(piece->child("PointData"), np, v_.pointData, first);
            arrays(piece->child("CellData"), nc, v_.cellData, first);
            first = false;
        }
        if (first) fail(dataset, "no <Piece> element");
        if (unusable_ > 0 && warnings_)
            warnings_->push_back(path_ + ": " + std::to_string(unusable_) +
                                 " cells are polyhedra or higher-order (Lagrange/Bezier) cells, which volume "
                                 "representations skip");
    }

    void cells(const XmlElement& piece, std::size_t n, std::size_t base, std::size_t np) {
        const XmlElement* e = piece.child("Cells");
        if (!e) fail(piece, "missing <Cells>");
        const mesh::VtkArray conn = named(*e, "connectivity");
        const mesh::VtkArray off = named(*e, "offsets");
        const mesh::VtkArray types = named(*e, "types");
        if (types.values.size() != n)
            fail(*e, "types has " + std::to_string(types.values.size()) + " values, expected " + std::to_string(n));
        // Offsets as VTK writes them (one end per cell) or with a leading 0.
        std::size_t skip = 0;
        if (off.values.size() == n + 1 && off.values[0] == 0) skip = 1;
        else if (off.values.size() != n)
            fail(*e, "offsets has " + std::to_string(off.values.size()) + " values, expected " + std::to_string(n));
        std::size_t begin = 0;
        for (std::size_t c = 0; c < n; ++c) {
            const double end = off.values[c + skip];
            if (!(end >= double(begin) && end <= double(conn.values.size())) || end != std::floor(end))
                fail(*e, "offsets must increase and stay within the " + std::to_string(conn.values.size()) +
                             " connectivity entries (cell " + std::to_string(c) + ")");
            const double tv = types.values[c];
            const int type = tv >= 0 && tv <= 255 && tv == std::floor(tv) ? int(tv) : -1;
            if (type < 0) fail(*e, "cell " + std::to_string(c) + " has type " + std::to_string(tv) + ", expected a VTK cell type");
            const std::size_t count = std::size_t(end) - begin;
            const auto lin = volume::linearCell(type);
            const std::size_t need = type == volume::kVoxel ? 8 : std::size_t(lin.corners);
            if (lin.corners > 0 && count < need)
                fail(*e, "cell " + std::to_string(c) + " of type " + std::to_string(type) + " has " +
                             std::to_string(count) + " points, expected at least " + std::to_string(need));
            if (type == volume::kPolyhedron || type >= 60) ++unusable_;
            for (std::size_t k = begin; k < std::size_t(end); ++k) {
                const double p = conn.values[k];
                if (!(p >= 0 && p < double(np)) || p != std::floor(p))
                    fail(*e, "connectivity references point " + std::to_string(static_cast<long long>(p)) +
                                 ", expected 0 to " + std::to_string(static_cast<long long>(np) - 1));
                v_.connectivity.push_back(static_cast<std::uint32_t>(base + std::size_t(p)));
            }
            v_.offsets.push_back(static_cast<std::uint32_t>(v_.connectivity.size()));
            v_.types.push_back(static_cast<std::uint8_t>(type));
            begin = std::size_t(end);
        }
    }

    std::vector<double> numbers(const XmlElement& e, const char* key, std::size_t count, bool required) const {
        const std::string* s = e.attribute(key);
        if (!s) {
            if (required) fail(e, std::string("missing attribute ") + key);
            return {};
        }
        std::istringstream in(*s);
        std::vector<double> out;
        std::string token;
        while (in >> token) {
            double v = 0;
            if (!mesh::parseDouble(token, v) || !std::isfinite(v))
                fail(e, std::string(key) + " holds '" + token + "', expected numbers");
            out.push_back(v);
        }
        if (out.size() != count)
            fail(e, std::string(key) + " has " + std::to_string(out.size()) + " numbers, expected " + std::to_string(count));
        return out;
    }

    void image(const XmlElement& dataset) {
        const auto whole = numbers(dataset, "WholeExtent", 6, true);
        for (int a = 0; a < 3; ++a) {
            if (whole[2 * a + 1] < whole[2 * a] || whole[2 * a] != std::floor(whole[2 * a]) ||
                whole[2 * a + 1] != std::floor(whole[2 * a + 1]))
                fail(dataset, "WholeExtent must hold integer pairs lo <= hi");
            const double n = whole[2 * a + 1] - whole[2 * a] + 1;
            if (n > 1 << 16) fail(dataset, "WholeExtent is too large (more than 65536 points on an axis)");
            v_.dims[a] = int(n);
        }
        if (v_.dims[0] < 2 || v_.dims[1] < 2 || v_.dims[2] < 2)
            fail(dataset, "WholeExtent " + std::to_string(v_.dims[0]) + " x " + std::to_string(v_.dims[1]) + " x " +
                              std::to_string(v_.dims[2]) +
                              " points is not a volume (expected at least 2 points on each axis)");
        // Checked before anything is allocated per point: a tiny file can claim a huge extent.
        const double points = double(v_.dims[0]) * double(v_.dims[1]) * double(v_.dims[2]);
        if (points > double(1ull << 28))
            fail(dataset, "WholeExtent holds " + std::to_string(static_cast<long long>(points)) +
                              " points; volumes of more than 2^28 (268,435,456) points are not read");
        const auto origin = numbers(dataset, "Origin", 3, false);
        const auto spacing = numbers(dataset, "Spacing", 3, false);
        const auto direction = numbers(dataset, "Direction", 9, false);
        if (!spacing.empty()) {
            v_.spacing = {spacing[0], spacing[1], spacing[2]};
            if (!(spacing[0] > 0 && spacing[1] > 0 && spacing[2] > 0)) fail(dataset, "Spacing must be positive");
        }
        if (!direction.empty()) std::copy(direction.begin(), direction.end(), v_.direction.begin());
        // Point (i, j, k) of the extent lies at Origin + Direction (Spacing * (lo + (i, j, k))).
        const Vec3 lo{v_.spacing.x * whole[0], v_.spacing.y * whole[2], v_.spacing.z * whole[4]};
        const auto& d = v_.direction;
        v_.origin = Vec3{origin.empty() ? 0 : origin[0], origin.empty() ? 0 : origin[1], origin.empty() ? 0 : origin[2]} +
                    Vec3{d[0] * lo.x + d[1] * lo.y + d[2] * lo.z, d[3] * lo.x + d[4] * lo.y + d[5] * lo.z,
                         d[6] * lo.x + d[7] * lo.y + d[8] * lo.z};
        const XmlElement* piece = nullptr;
        for (const auto& c : dataset.children)
            if (c->name == "Piece") {
                if (piece) fail(*c, "several <Piece> elements; images split into pieces are not read");
                piece = c.get();
            }
        if (!piece) fail(dataset, "no <Piece> element");
        if (piece->attribute("Extent") && numbers(*piece, "Extent", 6, true) != whole)
            fail(*piece, "the piece's Extent differs from WholeExtent; images split into pieces are not read");
        arrays(piece->child("PointData"), v_.pointCount(), v_.pointData, true);
        arrays(piece->child("CellData"), v_.cellCount(), v_.cellData, true);
    }

    std::string path_;
    std::vector<std::string>* warnings_;
    std::string data_;
    mesh::VtkXmlDocument doc_;
    mesh::VtkXmlEncoding enc_;
    VolumeMesh v_;
    std::size_t unusable_ = 0;
};

}  // namespace

VolumeMesh readVolume(const std::string& path, std::vector<std::string>* warnings) {
    const std::string ext = lowerExtension(path);
    if (ext != ".vtu" && ext != ".vti")
        throw Error(path + ": volumes are read from .vtu (UnstructuredGrid) or .vti (ImageData) files");
    return VolumeReader(path, warnings).read();
}

bool isVolumeFile(const std::string& path) {
    const std::string ext = lowerExtension(path);
    if (ext == ".vti") return true;
    if (ext != ".vtu") return false;
    return readVolume(path).volumeCellCount() > 0;
}

}  // namespace darkroom
