// PLY (ASCII, binary little- and big-endian): vertices with any scalar
// properties, faces (polygons) and tristrips (-1 restarts), other elements
// skipped. Properties other than x, y, z become fields named as in the file.
// Binary triangle meshes are read by ply_triangles.h, straight into the
// surface's arrays; this general reader takes every other file, and every
// file that one finds wrong, so that it alone words the errors.
#include "../poly_mesh.h"
#include "ply_header.h"
#include "ply_triangles.h"

#include <darkroom/data/formats/number_text.h>

#include <darkroom/scene/mesh_readers.h>
#include <darkroom/limits.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <optional>

namespace darkroom {
namespace {

using mesh::ValueType;
using ply::Element;
using ply::Property;

class PlyReader {
public:
    PlyReader(const std::string& path, std::string_view data) : path_(path), cur_(path, data) {}

    mesh::PolyMesh read() {
        header_ = ply::readHeader(path_, cur_);
        ascii_ = header_.ascii;
        bigEndian_ = header_.bigEndian;
        mesh_.source = path_;
        ply::checkElements(path_, header_, cur_.remaining());
        // An element without properties has nothing to read: it is skipped
        // whole, so its count allocates nothing.
        for (const auto& e : header_.elements)
            if (e.properties.empty()) continue;
            else if (e.name == "face") faceCount_ = e.count;
            else if (e.name == "tristrips") stripCount_ = e.count;
            else if (e.name == "vertex") vertexCount_ = e.count;
        mesh_.cellCount = faceCount_ + stripCount_;
        for (const auto& e : header_.elements)
            if (!e.properties.empty()) readElement(e);
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const Element& e, std::size_t i, const std::string& what) {
        if (ascii_) cur_.fail(what + " (element '" + e.name + "' " + std::to_string(i) + ")");
        throw Error(path_ + ": element '" + e.name + "' " + std::to_string(i) + ": " + what);
    }

    double value(const Element& e, std::size_t i, const Property& p, ValueType t) {
        if (ascii_) {
            const std::string_view tok = cur_.token();
            double v = 0;
            if (tok.empty()) fail(e, i, "unexpected end of file, expected a value of property '" + p.name + "'");
            if (!mesh::parseDouble(tok, v))
                fail(e, i, "expected a number for property '" + p.name + "', got '" + std::string(tok.substr(0, 40)) + "'");
            return v;
        }
        const char* b = cur_.take(mesh::sizeOf(t));
        if (!b) fail(e, i, "file ends early (truncated) while reading property '" + p.name + "'");
        return mesh::loadValue(t, b, bigEndian_);
    }

    // Faces and strips share cell arrays of the same name; NaN where a cell lacks it.
    int cellArray(const std::string& name) {
        for (std::size_t i = 0; i < mesh_.cellData.size(); ++i)
            if (mesh_.cellData[i].name == name) return int(i);
        mesh_.cellData.push_back({name, 1, std::vector<float>(mesh_.cellCount, std::numeric_limits<float>::quiet_NaN())});
        return int(mesh_.cellData.size() - 1);
    }

    void readElement(const Element& e) {
        ply::checkCount(path_, header_, e, cur_.remaining());  // again: earlier elements took their share
        const bool isVertex = e.name == "vertex", isFace = e.name == "face", isStrip = e.name == "tristrips";
        // Where each scalar property goes: x/y/z, a field, or nowhere.
        std::vector<int> fieldIndex(e.properties.size(), -1);
        std::vector<int> coord(e.properties.size(), -1);
        const std::size_t cellBase = isStrip ? faceCount_ : 0;
        if (isVertex) mesh_.points.assign(e.count * 3, 0.f);
        for (std::size_t k = 0; k < e.properties.size(); ++k) {
            const Property& p = e.properties[k];
            if (p.isList) continue;
            if (isVertex) {
                if (p.name == "x") coord[k] = 0;
                else if (p.name == "y") coord[k] = 1;
                else if (p.name == "z") coord[k] = 2;
                else {
                    fieldIndex[k] = int(mesh_.pointData.size());
                    mesh_.pointData.push_back({p.name, 1, std::vector<float>(e.count)});
                }
            } else if (isFace || isStrip) {
                fieldIndex[k] = cellArray(p.name);
            }
        }
        // Pointers taken once every array exists, so none can be invalidated.
        std::vector<std::vector<float>*> fields(e.properties.size(), nullptr);
        for (std::size_t k = 0; k < e.properties.size(); ++k)
            if (fieldIndex[k] >= 0)
                fields[k] = &(isVertex ? mesh_.pointData : mesh_.cellData)[std::size_t(fieldIndex[k])].values;
        mesh::CellList* cells = isFace ? &mesh_.polygons : isStrip ? &mesh_.strips : nullptr;
        for (std::size_t i = 0; i < e.count; ++i) {
            for (std::size_t k = 0; k < e.properties.size(); ++k) {
                const Property& p = e.properties[k];
                if (!p.isList) {
                    const double v = value(e, i, p, p.type);
                    if (coord[k] >= 0) mesh_.points[3 * i + std::size_t(coord[k])] = float(v);
                    else if (fields[k]) (*fields[k])[(isVertex ? 0 : cellBase) + i] = float(v);
                    continue;
                }
                const double n = value(e, i, p, p.countType);
                if (!(n >= 0) || n != std::floor(n)) fail(e, i, "list length of '" + p.name + "' must be a non-negative integer");
                if (n > double(cur_.remaining())) fail(e, i, "list '" + p.name + "' is longer than the rest of the file (truncated?)");
                const bool indices = cells && (p.name == "vertex_indices" || p.name == "vertex_index");
                for (std::size_t j = 0; j < std::size_t(n); ++j) {
                    const double v = value(e, i, p, p.type);
                    if (!indices) continue;
                    if (isStrip && v == -1) {
                        cells->connectivity.push_back(mesh::kStripRestart);
                        continue;
                    }
                    if (!(v >= 0 && v < double(vertexCount_)) || v != std::floor(v))
                        fail(e, i, "vertex index " + mesh::numberText(v) + " out of range, expected 0 to " +
                                       std::to_string(static_cast<long long>(vertexCount_) - 1));
                    cells->connectivity.push_back(static_cast<std::uint32_t>(v));
                }
            }
            if (cells) cells->close(static_cast<std::uint32_t>(cellBase + i));
        }
    }

    std::string path_;
    mesh::TextCursor cur_;
    ply::Header header_;
    bool ascii_ = false, bigEndian_ = false;
    std::size_t faceCount_ = 0, stripCount_ = 0, vertexCount_ = 0;
    mesh::PolyMesh mesh_;
};

}  // namespace

std::vector<SceneObject> readPly(const std::string& path) { return readPly(path, PlyReadOptions{}); }

std::vector<SceneObject> readPly(const std::string& path, const PlyReadOptions& options) {
    const std::string name = std::filesystem::path(path).stem().string();
    if (options.direct) {
        std::optional<SceneObject> surface = ply::readTriangles(path, name, std::max<std::size_t>(options.windowBytes, 1));
        if (surface) {
            std::vector<SceneObject> out;
            out.push_back(std::move(*surface));
            return out;
        }
    }
    const std::string data = mesh::readWholeFile(path, "mesh");
    PlyReader reader(path, data);
    return mesh::buildSceneObjects(reader.read(), name);
}

}  // namespace darkroom
