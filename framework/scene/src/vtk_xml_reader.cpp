// VTK XML PolyData (.vtp) and UnstructuredGrid (.vtu). DataArrays in ascii,
// binary (inline base64) or appended (raw or base64) form, zlib-compressed or
// not, UInt32 or UInt64 headers, either byte order, several pieces merged.
#include <darkroom/data/formats/number_text.h>
#include <darkroom/data/formats/binary_values.h>
#include "poly_mesh.h"
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/data/formats/vtk_data_array.h>
#include <darkroom/data/formats/xml_document.h>

#include <darkroom/scene/mesh_readers.h>

#include <cctype>
#include <cmath>
#include <filesystem>

namespace darkroom {
namespace {

using mesh::ValueType;
using mesh::XmlElement;

using Array = mesh::VtkArray;

class XmlReader {
public:
    XmlReader(const std::string& path, std::vector<std::string>* warnings) : warnings_(warnings) { f_.path = path; }

    mesh::PolyMesh read(std::string_view data) {
        doc_ = mesh::parseVtkXml(data, f_.path);
        f_.doc = &doc_;
        const XmlElement& root = *doc_.root;
        if (root.name != "VTKFile") fail(root, "expected <VTKFile> as the root element, got <" + root.name + ">");
        const std::string type = root.attributeOr("type", "");
        if (type != "PolyData" && type != "UnstructuredGrid")
            fail(root, "unsupported dataset type '" + type + "' (expected PolyData or UnstructuredGrid)");
        f_ = mesh::vtkXmlEncoding(doc_, f_.path);
        const XmlElement* dataset = root.child(type);
        if (!dataset) fail(root, "missing <" + type + "> element");
        m_.source = f_.path;
        bool anyPiece = false;
        for (const auto& piece : dataset->children)
            if (piece->name == "Piece") {
                readPiece(*piece, type == "PolyData");
                anyPiece = true;
            }
        if (!anyPiece) fail(*dataset, "no <Piece> element");
        if (skipped3d_ > 0 && warnings_)
            warnings_->push_back(f_.path + ": skipped " + std::to_string(skipped3d_) +
                                 " cells that are neither vertices, lines nor 2D faces (3D or higher-order cells)");
        if (skipped3d_ > 0 && m_.vertices.size() + m_.lines.size() + m_.polygons.size() + m_.strips.size() == 0)
            throw Error(f_.path + ": only 3D or higher-order cells (" + std::to_string(skipped3d_) +
                        "), nothing to draw: extract a surface first (e.g. ParaView's Extract Surface)");
        return std::move(m_);
    }

private:
    [[noreturn]] void fail(const XmlElement& e, const std::string& what) const {
        throw Error(f_.path + ":" + std::to_string(e.line) + ": " + what);
    }

    std::size_t countAttr(const XmlElement& e, const char* key) const { return mesh::vtkCountAttribute(e, f_.path, key); }

    Array dataArray(const XmlElement& e, std::size_t maxTuples = mesh::kAnyTuples) const {
        return mesh::readVtkDataArray(e, f_, maxTuples);
    }

    // The DataArray named `name` inside `parent` (or the first one when name is empty).
    Array required(const XmlElement& parent, const std::string& name, std::size_t expected, int components) const {
        for (const auto& c : parent.children) {
            if (c->name != "DataArray" || (!name.empty() && c->attributeOr("Name", "") != name)) continue;
            Array a = dataArray(*c, expected);
            if (a.values.size() != expected * std::size_t(components))
                fail(*c, "DataArray '" + a.name + "' has " + std::to_string(a.values.size()) + " values, expected " +
                             std::to_string(expected) + " x " + std::to_string(components));
            return a;
        }
        fail(parent, "<" + parent.name + "> lacks the DataArray" + (name.empty() ? std::string() : " '" + name + "'"));
    }

    void arrays(const XmlElement* parent, std::size_t tuples, std::vector<mesh::DataArray>& out, bool firstPiece) const {
        if (!parent) {
            if (!firstPiece && !out.empty()) fail(*doc_.root, "pieces carry different data arrays");
            return;
        }
        std::size_t k = 0;
        for (const auto& c : parent->children) {
            if (c->name != "DataArray") continue;
            const Array a = dataArray(*c, tuples);
            if (a.values.size() != tuples * std::size_t(a.components))
                fail(*c, "DataArray '" + a.name + "' has " + std::to_string(a.values.size()) + " values, expected " +
                             std::to_string(tuples) + " x " + std::to_string(a.components));
            if (firstPiece) {
                out.push_back({a.name, a.components, std::vector<float>(a.values.begin(), a.values.end())});
            } else {
                if (k >= out.size() || out[k].name != a.name || out[k].components != a.components)
                    fail(*c, "pieces carry different data arrays ('" + a.name + "' is not in the first piece at this position)");
                out[k].values.insert(out[k].values.end(), a.values.begin(), a.values.end());
            }
            ++k;
        }
        if (!firstPiece && k != out.size()) fail(*parent, "pieces carry different data arrays");
    }

    std::uint32_t pointIndex(double v, std::size_t base, std::size_t np, const XmlElement& e) const {
        if (!(v >= 0 && v < double(np)) || v != std::floor(v))
            fail(e, "connectivity references point " + mesh::numberText(v) + ", expected 0 to " +
                        std::to_string(static_cast<long long>(np) - 1));
        return static_cast<std::uint32_t>(base + std::size_t(v));
    }

    // Offsets as VTK writes them: one end per cell, or begins with a leading 0 and a final end.
    std::vector<std::size_t> cellBounds(const Array& off, std::size_t cells, std::size_t connSize, const XmlElement& e) const {
        std::vector<std::size_t> b{0};
        std::size_t first = 0;
        if (off.values.size() == cells + 1 && cells > 0 && off.values[0] == 0) first = 1;
        else if (off.values.size() != cells)
            fail(e, "offsets has " + std::to_string(off.values.size()) + " values, expected " + std::to_string(cells));
        for (std::size_t i = first; i < off.values.size(); ++i) {
            const double v = off.values[i];
            if (!(v >= double(b.back()) && v <= double(connSize)))
                fail(e, "offsets must increase and stay within the " + std::to_string(connSize) + " connectivity entries");
            b.push_back(std::size_t(v));
        }
        return b;
    }

    void polyCells(const XmlElement& piece, const char* tag, std::size_t n, mesh::CellList& list, std::size_t pointBase,
                   std::size_t np, std::size_t cellBase) {
        if (n == 0) return;
        const XmlElement* e = piece.child(tag);
        if (!e) fail(piece, std::string("missing <") + tag + "> for " + std::to_string(n) + " cells");
        const Array conn = named(*e, "connectivity");
        const Array off = named(*e, "offsets", n + 1);
        const auto bounds = cellBounds(off, n, conn.values.size(), *e);
        for (std::size_t c = 0; c < n; ++c) {
            for (std::size_t k = bounds[c]; k < bounds[c + 1]; ++k) list.connectivity.push_back(pointIndex(conn.values[k], pointBase, np, *e));
            list.close(static_cast<std::uint32_t>(cellBase + c));
        }
    }

    // A DataArray whose length the piece does not state exactly (connectivity, offsets).
    Array named(const XmlElement& parent, const std::string& name, std::size_t maxTuples = mesh::kAnyTuples) const {
        for (const auto& c : parent.children)
            if (c->name == "DataArray" && c->attributeOr("Name", "") == name) return dataArray(*c, maxTuples);
        fail(parent, "<" + parent.name + "> lacks the DataArray '" + name + "'");
    }

    void readPiece(const XmlElement& piece, bool polyData) {
        const bool first = m_.points.empty() && m_.cellCount == 0;
        const std::size_t np = countAttr(piece, "NumberOfPoints");
        const std::size_t pointBase = m_.pointCount(), cellBase = m_.cellCount;
        if (np > 0) {
            const XmlElement* pts = piece.child("Points");
            if (!pts) fail(piece, "missing <Points>");
            const Array p = required(*pts, "", np, 3);
            m_.points.insert(m_.points.end(), p.values.begin(), p.values.end());
        }
        std::size_t cells = 0;
        if (polyData) {
            const std::size_t nv = countAttr(piece, "NumberOfVerts"), nl = countAttr(piece, "NumberOfLines"),
                              npo = countAttr(piece, "NumberOfPolys"), ns = countAttr(piece, "NumberOfStrips");
            // PolyData cell data runs over verts, lines, polys, strips in that order.
            polyCells(piece, "Verts", nv, m_.vertices, pointBase, np, cellBase);
            polyCells(piece, "Lines", nl, m_.lines, pointBase, np, cellBase + nv);
            polyCells(piece, "Polys", npo, m_.polygons, pointBase, np, cellBase + nv + nl);
            polyCells(piece, "Strips", ns, m_.strips, pointBase, np, cellBase + nv + nl + npo);
            cells = nv + nl + npo + ns;
        } else {
            cells = countAttr(piece, "NumberOfCells");
            if (cells > 0) unstructuredCells(piece, cells, pointBase, np, cellBase);
        }
        m_.cellCount += cells;
        arrays(piece.child("PointData"), np, m_.pointData, first);
        arrays(piece.child("CellData"), cells, m_.cellData, first);
    }

    void unstructuredCells(const XmlElement& piece, std::size_t n, std::size_t pointBase, std::size_t np, std::size_t cellBase) {
        const XmlElement* e = piece.child("Cells");
        if (!e) fail(piece, "missing <Cells>");
        const Array conn = named(*e, "connectivity");
        const Array off = named(*e, "offsets", n + 1);
        const Array types = required(*e, "types", n, 1);
        const auto bounds = cellBounds(off, n, conn.values.size(), *e);
        for (std::size_t c = 0; c < n; ++c) {
            mesh::CellList* list = nullptr;
            const double tv = types.values[c];
            const int type = tv >= 0 && tv <= 255 ? int(tv) : -1;
            switch (type) {
                case 1: case 2: list = &m_.vertices; break;      // vertex, poly-vertex
                case 3: case 4: list = &m_.lines; break;         // line, polyline
                case 5: case 7: case 8: case 9: list = &m_.polygons; break;  // triangle, polygon, pixel, quad
                case 6: list = &m_.strips; break;                // triangle strip
                default: ++skipped3d_; continue;
            }
            const std::size_t b = bounds[c], len = bounds[c + 1] - bounds[c];
            for (std::size_t k = 0; k < len; ++k) {
                // A pixel's points run row by row (0,1,3,2 around it); reorder to a cycle.
                const std::size_t kk = (type == 8 && len == 4) ? std::size_t(k == 2 ? 3 : k == 3 ? 2 : k) : k;
                list->connectivity.push_back(pointIndex(conn.values[b + kk], pointBase, np, *e));
            }
            list->close(static_cast<std::uint32_t>(cellBase + c));
        }
    }

    mesh::VtkXmlEncoding f_;
    mesh::VtkXmlDocument doc_;
    mesh::PolyMesh m_;
    std::vector<std::string>* warnings_;
    std::size_t skipped3d_ = 0;
};

}  // namespace

std::vector<SceneObject> readVtkXml(const std::string& path, std::vector<std::string>* warnings) {
    const std::string data = mesh::readWholeFile(path, "mesh");
    XmlReader reader(path, warnings);
    return mesh::buildSceneObjects(reader.read(data), std::filesystem::path(path).stem().string());
}

}  // namespace darkroom
