// PLY (ASCII, binary little- and big-endian): vertices with any scalar
// properties, faces (polygons) and tristrips (-1 restarts), other elements
// skipped. Properties other than x, y, z become fields named as in the file.
#include <darkroom/data/formats/number_text.h>
#include <darkroom/data/formats/binary_values.h>
#include "poly_mesh.h"
#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/scene/mesh_readers.h>
#include <darkroom/limits.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>

namespace darkroom {
namespace {

using mesh::ValueType;

struct Property {
    std::string name;
    bool isList = false;
    ValueType countType = ValueType::UInt8;
    ValueType type = ValueType::Float32;
};

struct Element {
    std::string name;
    std::size_t count = 0;
    std::vector<Property> properties;
    int line = 0;  // of its 'element' line, for messages
};

std::optional<ValueType> plyType(std::string_view s) {
    if (s == "char" || s == "int8") return ValueType::Int8;
    if (s == "uchar" || s == "uint8") return ValueType::UInt8;
    if (s == "short" || s == "int16") return ValueType::Int16;
    if (s == "ushort" || s == "uint16") return ValueType::UInt16;
    if (s == "int" || s == "int32") return ValueType::Int32;
    if (s == "uint" || s == "uint32") return ValueType::UInt32;
    if (s == "float" || s == "float32") return ValueType::Float32;
    if (s == "double" || s == "float64") return ValueType::Float64;
    return std::nullopt;
}

class PlyReader {
public:
    PlyReader(const std::string& path, std::string_view data) : path_(path), cur_(path, data) {}

    mesh::PolyMesh read() {
        readHeader();
        mesh_.source = path_;
        checkElements();
        // An element without properties has nothing to read: it is skipped
        // whole, so its count allocates nothing.
        for (const auto& e : elements_)
            if (e.properties.empty()) continue;
            else if (e.name == "face") faceCount_ = e.count;
            else if (e.name == "tristrips") stripCount_ = e.count;
            else if (e.name == "vertex") vertexCount_ = e.count;
        mesh_.cellCount = faceCount_ + stripCount_;
        for (const auto& e : elements_)
            if (!e.properties.empty()) readElement(e);
        return std::move(mesh_);
    }

private:
    [[noreturn]] void fail(const Element& e, std::size_t i, const std::string& what) {
        if (ascii_) cur_.fail(what + " (element '" + e.name + "' " + std::to_string(i) + ")");
        throw Error(path_ + ": element '" + e.name + "' " + std::to_string(i) + ": " + what);
    }

    void readHeader() {
        const std::string_view magic = cur_.restOfLine();
        if (magic != "ply") throw Error(path_ + ":1: missing PLY header: expected 'ply' on the first line");
        bool sawFormat = false;
        for (;;) {
            if (cur_.atEnd()) cur_.fail("unexpected end of file in the PLY header, expected 'end_header'");
            const int line = cur_.line();
            const auto t = mesh::splitBlanks(cur_.restOfLine());
            auto bad = [&](const std::string& what) {
                throw InputError(path_ + ":" + std::to_string(line) + ": " + what);
            };
            if (t.empty()) continue;
            if (t[0] == "comment" || t[0] == "obj_info") continue;
            if (t[0] == "end_header") break;
            if (t[0] == "format") {
                if (t.size() != 3) bad("expected 'format <ascii|binary_little_endian|binary_big_endian> 1.0'");
                if (t[1] == "ascii") ascii_ = true;
                else if (t[1] == "binary_little_endian") bigEndian_ = false;
                else if (t[1] == "binary_big_endian") bigEndian_ = true;
                else bad("unknown PLY format '" + std::string(t[1]) + "', expected ascii, binary_little_endian or binary_big_endian");
                sawFormat = true;
            } else if (t[0] == "element") {
                long long n = 0;
                if (t.size() != 3 || !mesh::parseInteger(t[2], n) || n < 0)
                    bad("expected 'element <name> <count>'");
                for (const auto& e : elements_)
                    if (e.name == t[1] && (e.name == "vertex" || e.name == "face" || e.name == "tristrips"))
                        bad("a second 'element " + e.name + "' (the first is on line " + std::to_string(e.line) +
                            "); expected one");
                elements_.push_back({std::string(t[1]), std::size_t(n), {}, line});
            } else if (t[0] == "property") {
                if (elements_.empty()) bad("'property' before any 'element'");
                Property p;
                if (t.size() == 5 && t[1] == "list") {
                    const auto ct = plyType(t[2]), vt = plyType(t[3]);
                    if (!ct || !vt) bad("unknown PLY type in list property '" + std::string(t[4]) + "'");
                    p = {std::string(t[4]), true, *ct, *vt};
                } else if (t.size() == 3) {
                    const auto vt = plyType(t[1]);
                    if (!vt) bad("unknown PLY type '" + std::string(t[1]) + "' (expected char, uchar, short, ushort, int, uint, float, double or int8..float64)");
                    p = {std::string(t[2]), false, ValueType::UInt8, *vt};
                } else {
                    bad("expected 'property <type> <name>' or 'property list <count type> <type> <name>'");
                }
                elements_.back().properties.push_back(p);
            } else {
                bad("unexpected '" + std::string(t[0]) + "' in the PLY header");
            }
        }
        if (!sawFormat) cur_.fail("PLY header without a 'format' line");
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

    // Checked once the header is read, before anything is allocated: the
    // vertices have x, y and z, and every count fits in the rest of the file.
    void checkElements() {
        const Element* vertex = nullptr;
        for (const auto& e : elements_) {
            checkCount(e);
            if (e.name == "vertex") vertex = &e;
        }
        if (!vertex) throw InputError(path_ + ": no 'element vertex' in the PLY header; expected vertices with x, y, z");
        for (const char* axis : {"x", "y", "z"}) {
            bool found = false;
            for (const auto& p : vertex->properties) found |= !p.isList && p.name == axis;
            if (!found)
                throw InputError(path_ + ":" + std::to_string(vertex->line) + ": 'element vertex' has no scalar property '" +
                                 axis + "'; expected x, y and z");
        }
        // Points and fields are float32: 4 bytes per scalar property.
        checkBytes(Limit::DecodedBytes, std::uint64_t(vertex->count) * 4 * std::max<std::size_t>(vertex->properties.size(), 3),
                   path_, "'element vertex' of " + std::to_string(vertex->count) + " vertices");
    }

    // Refuses counts the rest of the file cannot hold before allocating for them:
    // each instance takes at least its fixed-size bytes (binary) or 2 characters per property,
    // and at least one (a line end) in all (ASCII).
    void checkCount(const Element& e) {
        std::size_t least = 0;
        for (const auto& p : e.properties) least += ascii_ ? 2 : mesh::sizeOf(p.isList ? p.countType : p.type);
        if (ascii_) least = std::max<std::size_t>(least, 1);
        if (least > 0 && e.count > cur_.remaining() / least)
            throw InputError(path_ + ":" + std::to_string(e.line) + ": element '" + e.name + "' declares " +
                             std::to_string(e.count) + " entries but the " + std::to_string(cur_.remaining()) +
                             " bytes left in the file hold at most " + std::to_string(cur_.remaining() / least) +
                             " (truncated?)");
    }

    void readElement(const Element& e) {
        checkCount(e);  // again: earlier elements took their share of the file
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
    bool ascii_ = false, bigEndian_ = false;
    std::vector<Element> elements_;
    std::size_t faceCount_ = 0, stripCount_ = 0, vertexCount_ = 0;
    mesh::PolyMesh mesh_;
};

}  // namespace

std::vector<SceneObject> readPly(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "mesh");
    PlyReader reader(path, data);
    return mesh::buildSceneObjects(reader.read(), std::filesystem::path(path).stem().string());
}

}  // namespace darkroom
