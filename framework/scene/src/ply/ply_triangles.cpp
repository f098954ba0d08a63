#include "ply_triangles.h"

#include "../poly_mesh.h"
#include "../windowed/record_windows.h"
#include "../windowed/typed_load.h"
#include "ply_header.h"

#include <darkroom/error.h>

#include <algorithm>
#include <type_traits>
#include <vector>

namespace darkroom::ply {
namespace {

using windowed::FileRangeReader;
using windowed::load;
using windowed::readRecords;
using windowed::Span;
using windowed::withType;

// A header longer than this (real ones are a few hundred bytes) goes to the
// general reader, which holds the whole file anyway.
constexpr std::size_t kHeaderBytes = std::size_t(1) << 16;

// One scalar property of a fixed-size record and where its values go:
// out[i * stride] for record i, as the float the general reader stores.
struct Column {
    std::size_t offset = 0;
    ValueType type = ValueType::Float32;
    float* out = nullptr;
    std::size_t stride = 1;
};

// A triangle face record: its count (3), its 3 indices, its scalars.
struct FaceLayout {
    std::size_t size = 0, countOffset = 0, indexOffset = 0;
    ValueType countType = ValueType::UInt8, indexType = ValueType::Int32;
    std::vector<Column> cells;
    std::vector<std::string> cellNames;
};

// Record i's value goes to out[i * stride], or, with `where`, to
// out[where[i] * stride] unless where[i] is kStripRestart (a dropped point).
void decodeColumn(const Column& c, std::size_t recordSize, const Span& s, bool swap,
                  const std::uint32_t* where = nullptr) {
    withType(c.type, [&](auto tag) {
        using T = decltype(tag);
        const char* p = s.window + s.begin * recordSize + c.offset;
        if (where) {
            for (std::size_t i = s.first + s.begin; i < s.first + s.end; ++i, p += recordSize)
                if (where[i] != mesh::kStripRestart)
                    c.out[std::size_t(where[i]) * c.stride] = float(double(load<T>(p, swap)));
            return;
        }
        float* out = c.out + (s.first + s.begin) * c.stride;
        for (std::size_t i = s.begin; i < s.end; ++i, p += recordSize, out += c.stride)
            *out = float(double(load<T>(p, swap)));
    });
}

// False at the first face that is not 3 indices of points in [0, points).
bool decodeTriangles(const FaceLayout& f, const Span& s, std::uint32_t* indices, std::uint64_t points, bool swap) {
    const bool triangles = withType(f.countType, [&](auto tag) {
        using T = decltype(tag);
        const char* p = s.window + s.begin * f.size + f.countOffset;
        for (std::size_t i = s.begin; i < s.end; ++i, p += f.size)
            if (load<T>(p, swap) != T(3)) return false;
        return true;
    });
    if (!triangles) return false;
    return withType(f.indexType, [&](auto tag) {
        using T = decltype(tag);
        if constexpr (std::is_floating_point_v<T>) {
            return false;  // whole-number floats are valid indices: the general reader checks them
        } else {
            const char* p = s.window + s.begin * f.size + f.indexOffset;
            std::uint32_t* out = indices + 3 * (s.first + s.begin);
            for (std::size_t i = s.begin; i < s.end; ++i, p += f.size, out += 3)
                for (std::size_t k = 0; k < 3; ++k) {
                    const T v = load<T>(p + k * sizeof(T), swap);
                    if constexpr (std::is_signed_v<T>)
                        if (v < 0) return false;
                    if (std::uint64_t(v) >= points) return false;
                    out[k] = static_cast<std::uint32_t>(v);
                }
            return true;
        }
    });
}

// The layout of a face element of triangles; nothing if it has another list
// or no vertex index list.
std::optional<FaceLayout> faceLayout(const Element& face) {
    FaceLayout f;
    int lists = 0;
    for (const auto& p : face.properties) {
        if (p.isList) {
            if ((p.name != "vertex_indices" && p.name != "vertex_index") || ++lists > 1) return std::nullopt;
            f.countOffset = f.size;
            f.countType = p.countType;
            f.indexOffset = f.size + mesh::sizeOf(p.countType);
            f.indexType = p.type;
            f.size += mesh::sizeOf(p.countType) + 3 * mesh::sizeOf(p.type);
        } else {
            f.cells.push_back({f.size, p.type, nullptr, 1});
            f.cellNames.push_back(p.name);
            f.size += mesh::sizeOf(p.type);
        }
    }
    if (lists != 1) return std::nullopt;
    return f;
}

// The surface's arrays, laid out as the general reader lays them out: point
// fields in property order (x, y and z are the positions), then cell fields
// (faces' properties of one name share one); points in the order the
// triangles first use them (mesh::renumberByFirstUse).
class TriangleMesh {
public:
    TriangleMesh(const Element& vertex, const Element& face, FaceLayout& layout, const std::string& name)
        : vertex_(vertex) {
        object_.name = name;
        object_.indices.resize(3 * face.count);
        for (const auto& p : vertex.properties) {
            const bool position = p.name == "x" || p.name == "y" || p.name == "z";
            pointField_.push_back(position ? -1 : int(object_.fields.size()));
            if (!position) object_.fields.push_back({p.name, ScalarField::Association::Point, {}});
        }
        const std::size_t firstCell = object_.fields.size();
        for (std::size_t c = 0; c < layout.cells.size(); ++c) {
            std::size_t k = firstCell;
            while (k < object_.fields.size() && object_.fields[k].name != layout.cellNames[c]) ++k;
            if (k == object_.fields.size())
                object_.fields.push_back(
                    {layout.cellNames[c], ScalarField::Association::Cell, std::vector<float>(face.count)});
            layout.cells[c].out = object_.fields[k].values.data();
        }
    }

    std::uint32_t* indices() { return object_.indices.data(); }

    // Once the triangles are read: their points numbered by first use, and
    // the columns that scatter each vertex record to its new number.
    const std::vector<std::uint32_t>& renumber() {
        std::size_t used = 0;
        newNumber_ = mesh::renumberByFirstUse(object_.indices, vertex_.count, used);
        object_.vertices.assign(4 * used, 0.f);
        for (int f : pointField_)
            if (f >= 0) object_.fields[std::size_t(f)].values.resize(used);
        std::size_t offset = 0;
        for (std::size_t k = 0; k < vertex_.properties.size(); ++k) {
            const auto& p = vertex_.properties[k];
            const std::size_t axis = p.name == "x" ? 0 : p.name == "y" ? 1 : 2;
            vertexColumns_.push_back(
                pointField_[k] < 0
                    ? Column{offset, p.type, object_.vertices.data() + axis, 4}
                    : Column{offset, p.type, object_.fields[std::size_t(pointField_[k])].values.data(), 1});
            offset += mesh::sizeOf(p.type);
        }
        return newNumber_;
    }

    const std::vector<Column>& vertexColumns() const { return vertexColumns_; }
    SceneObject take() { return std::move(object_); }

private:
    const Element& vertex_;
    SceneObject object_;
    std::vector<int> pointField_;  // per vertex property: its field, or -1 for a position
    std::vector<std::uint32_t> newNumber_;
    std::vector<Column> vertexColumns_;
};

// The vertex and face elements if the file is of the kind read here.
std::optional<std::pair<const Element*, const Element*>> vertexAndFaces(const Header& h) {
    const Element *vertex = nullptr, *face = nullptr;
    for (const auto& e : h.elements) {
        if (e.properties.empty()) continue;  // nothing to read, 0 bytes
        if (e.name == "face") face = &e;
        else if (e.fixedSize() == 0 || e.name == "tristrips") return std::nullopt;
        else if (e.name == "vertex") vertex = &e;
    }
    if (!vertex || !face || face->count == 0) return std::nullopt;
    return std::make_pair(vertex, face);
}

}  // namespace

std::optional<SceneObject> readTriangles(const std::string& path, const std::string& name, std::size_t windowBytes) {
    const FileRangeReader file(path);
    if (!file.ok()) return std::nullopt;
    std::string head(std::size_t(std::min<std::uint64_t>(file.size(), kHeaderBytes)), '\0');
    if (!file.read(0, head.size(), head.data())) return std::nullopt;
    mesh::TextCursor cur(path, head);
    Header header;
    try {
        header = readHeader(path, cur);
    } catch (const Error&) {
        if (head.size() < file.size()) return std::nullopt;  // perhaps a longer header: the general reader decides
        throw;
    }
    if (header.ascii) return std::nullopt;
    checkElements(path, header, std::size_t(file.size() - cur.position()));
    const auto elements = vertexAndFaces(header);
    if (!elements) return std::nullopt;
    const Element* vertex = elements->first;
    const Element* face = elements->second;
    std::optional<FaceLayout> layout = faceLayout(*face);
    if (!layout) return std::nullopt;

    // Where each element's records start; fixed sizes make them known now.
    const std::uint64_t body = cur.position();
    std::uint64_t vertexAt = 0, faceAt = 0, offset = body;
    for (const auto& e : header.elements) {
        if (e.properties.empty()) continue;
        const std::size_t size = &e == face ? layout->size : e.fixedSize();
        if (e.count > (file.size() - offset) / size) return std::nullopt;  // shorter than its header says
        if (&e == vertex) vertexAt = offset;
        if (&e == face) faceAt = offset;
        offset += std::uint64_t(e.count) * size;
    }

    // Triangles first (their points' numbering depends on them), then the
    // points, each written straight to its new number.
    TriangleMesh mesh(*vertex, *face, *layout, name);
    const bool swap = header.bigEndian != mesh::isHostBigEndian();
    std::vector<char> buffer;
    const bool trianglesRead =
        readRecords(file, faceAt, face->count, layout->size, windowBytes, buffer, [&](const Span& s) {
            if (!decodeTriangles(*layout, s, mesh.indices(), vertex->count, swap)) return false;
            for (const auto& c : layout->cells) decodeColumn(c, layout->size, s, swap);
            return true;
        });
    if (!trianglesRead) return std::nullopt;
    const std::uint32_t* newNumber = mesh.renumber().data();
    const std::size_t vertexSize = vertex->fixedSize();
    const bool pointsRead =
        readRecords(file, vertexAt, vertex->count, vertexSize, windowBytes, buffer, [&](const Span& s) {
            for (const auto& c : mesh.vertexColumns()) decodeColumn(c, vertexSize, s, swap, newNumber);
            return true;
        });
    if (!pointsRead) return std::nullopt;
    return mesh.take();
}

}  // namespace darkroom::ply
