// STL (stereolithography), ASCII and binary: a soup of triangles, each with
// its own three positions. Facet normals are ignored (capture computes
// normals from the vertices: each triangle's, or averaged at the vertices)
// and so is the binary attribute word (some tools keep a colour there).
// Triangles of zero area are kept (a ray never hits them); a non-finite
// coordinate is refused.
//
// Identical positions are merged into one vertex, numbered in first use, so
// an STL reads as the same vertices and triangles as the OBJ or PLY of the
// same mesh, point lists (Spheres) see each position once, and the vertex
// array is about a sixth of the soup's. A hash map on the floats' bits costs
// about 0.2 s per million triangles (measured: docs/scene-format.md).
#include "poly_mesh.h"
#include <darkroom/data/formats/binary_values.h>
#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <array>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <optional>
#include <unordered_map>

namespace darkroom {
namespace {

constexpr std::uint64_t kBinaryHeaderBytes = 84, kBinaryTriangleBytes = 50;  // 80-byte text, uint32 count

std::string clip(std::string_view s) { return std::string(s.substr(0, 40)); }

// One vertex per distinct position, keyed by the coordinates' bits (exact:
// STL writers repeat a shared vertex's floats bit for bit).
class VertexMerger {
public:
    explicit VertexMerger(mesh::PolyMesh& m) : mesh_(m) {}
    void reserve(std::size_t triangles) { map_.reserve(triangles / 2 + 8); }

    std::uint32_t add(const float* p) {
        Key k;
        for (int c = 0; c < 3; ++c) {
            const float v = p[c] == 0.f ? 0.f : p[c];  // -0 and +0 are one position
            std::memcpy(&k[std::size_t(c)], &v, 4);
        }
        const auto [it, inserted] = map_.try_emplace(k, static_cast<std::uint32_t>(mesh_.pointCount()));
        if (inserted) mesh_.points.insert(mesh_.points.end(), p, p + 3);
        return it->second;
    }

private:
    using Key = std::array<std::uint32_t, 3>;
    struct Hash {
        std::size_t operator()(const Key& k) const {
            std::uint64_t h = (std::uint64_t(k[0]) << 32 | k[1]) * 0x9e3779b97f4a7c15ull ^ k[2];
            h ^= h >> 31;  // splitmix64's finaliser: every input bit reaches the bucket bits
            h *= 0xbf58476d1ce4e5b9ull;
            h ^= h >> 29;
            return std::size_t(h);
        }
    };
    mesh::PolyMesh& mesh_;
    std::unordered_map<Key, std::uint32_t, Hash> map_;
};

// Appends one triangle (9 floats) as one cell.
void addTriangle(mesh::PolyMesh& m, VertexMerger& merge, const float* v) {
    for (int c = 0; c < 3; ++c) m.polygons.connectivity.push_back(merge.add(v + 3 * c));
    m.polygons.close(static_cast<std::uint32_t>(m.polygons.size()));
}

// Points are float32: a coordinate beyond its range is as unusable as inf or
// NaN (the bounds and so the cameras would be).
std::string nonFinite(float x) {
    if (std::isfinite(x)) return {};
    return std::string("a non-finite coordinate (") + (std::isnan(x) ? "nan" : "inf") + "); expected finite numbers";
}

// The triangle count a binary file's size agrees with; nullopt if none does.
std::optional<std::uint32_t> binaryCount(std::string_view data) {
    if (data.size() < kBinaryHeaderBytes) return std::nullopt;
    const auto n = static_cast<std::uint32_t>(mesh::loadValue(mesh::ValueType::UInt32, data.data() + 80, false));
    if (kBinaryHeaderBytes + kBinaryTriangleBytes * n != data.size()) return std::nullopt;
    return n;
}

// ASCII when the size is no binary file's, the text starts with "solid" and
// holds no NUL. Many binary files' headers begin with "solid" too (some CAD
// exporters write them so); the size tells them apart, and a truncated one still has
// NULs in its floats, so it is reported as a binary file of the wrong size.
bool isAscii(std::string_view data) {
    if (binaryCount(data)) return false;
    const std::size_t b = data.find_first_not_of(" \t\r\n");
    if (b == std::string_view::npos || data.size() - b < 5) return false;
    for (std::size_t i = 0; i < 5; ++i)
        if (std::tolower(static_cast<unsigned char>(data[b + i])) != "solid"[i]) return false;
    return data.find('\0') == std::string_view::npos;
}

mesh::PolyMesh readBinary(const std::string& path, std::string_view data) {
    if (data.size() < kBinaryHeaderBytes)
        throw InputError(path + ": " + std::to_string(data.size()) + " bytes: neither an ASCII STL (expected 'solid' "
                         "first) nor a binary one (expected an 80-byte header and a triangle count, 84 bytes at least)");
    const auto count = binaryCount(data);
    if (!count) {
        const auto n = static_cast<std::uint64_t>(mesh::loadValue(mesh::ValueType::UInt32, data.data() + 80, false));
        throw InputError(path + ": binary STL header declares " + std::to_string(n) + " triangles, which take 84 + 50 x " +
                         std::to_string(n) + " = " + std::to_string(kBinaryHeaderBytes + kBinaryTriangleBytes * n) +
                         " bytes, but the file has " + std::to_string(data.size()) +
                         " (truncated, or not an STL file? an ASCII STL starts with 'solid' and holds no NUL byte)");
    }
    // Indices and offsets are 32-bit; then the soup's floats within the decoded limit.
    if (*count > 0xffffffffu / 3)
        throw InputError(path + ": " + std::to_string(*count) + " triangles; at most " +
                         std::to_string(0xffffffffu / 3) + " are supported (32-bit indices)");
    checkBytes(Limit::DecodedBytes, std::uint64_t(*count) * 36, path, std::to_string(*count) + " STL triangles");
    mesh::PolyMesh m;
    m.source = path;
    VertexMerger merge(m);
    merge.reserve(*count);
    m.polygons.connectivity.reserve(std::size_t(*count) * 3);
    for (std::uint32_t i = 0; i < *count; ++i) {
        // Each record: normal (skipped), three vertices, the attribute word (skipped).
        const char* p = data.data() + kBinaryHeaderBytes + kBinaryTriangleBytes * i + 12;
        float v[9];
        for (std::size_t k = 0; k < 9; ++k) {
            v[k] = float(mesh::loadValue(mesh::ValueType::Float32, p + 4 * k, false));
            if (const std::string problem = nonFinite(v[k]); !problem.empty())
                throw InputError(path + ": triangle " + std::to_string(i) + " (byte " +
                                 std::to_string(kBinaryHeaderBytes + kBinaryTriangleBytes * i) + "): vertex " +
                                 std::to_string(k / 3) + " has " + problem);
        }
        addTriangle(m, merge, v);
    }
    m.cellCount = *count;
    return m;
}

class AsciiStl {
public:
    AsciiStl(const std::string& path, std::string_view data) : cur_(path, data), merge_(mesh_) { mesh_.source = path; }

    // Several "solid ... endsolid" blocks (some tools join files so) are one mesh.
    mesh::PolyMesh read() {
        do solid();
        while (!cur_.atEnd());
        mesh_.cellCount = mesh_.polygons.size();
        return std::move(mesh_);
    }

private:
    static bool same(std::string_view a, std::string_view b) {
        if (a.size() != b.size()) return false;
        for (std::size_t i = 0; i < a.size(); ++i)
            if (std::tolower(static_cast<unsigned char>(a[i])) != b[i]) return false;
        return true;
    }

    [[noreturn]] void fail(const std::string& what) const {
        throw InputError(cur_.source() + ":" + std::to_string(cur_.line()) + ": " + what);
    }

    // The next token; the end of the file is an error saying what was expected
    // (messages are built only on failure: this runs for every token).
    std::string_view need(std::string_view expected, const char* context = "") {
        const std::string_view t = cur_.token();
        if (t.empty()) fail("unexpected end of file, expected " + std::string(expected) + context + " (truncated?)");
        return t;
    }

    // The next token, which must be `word` (any case, as exporters write it).
    void keyword(std::string_view word, const char* context = "") {
        const std::string_view t = cur_.token();
        if (same(t, word)) return;
        const std::string expected = "'" + std::string(word) + "'" + context;
        fail(t.empty() ? "unexpected end of file, expected " + expected + " (truncated?)"
                       : "expected " + expected + ", got '" + clip(t) + "'");
    }

    void solid() {
        keyword("solid");
        cur_.restOfLine();  // the name
        for (;;) {
            const std::string_view t = need("'facet' or 'endsolid'");
            if (same(t, "endsolid")) break;
            if (!same(t, "facet")) fail("expected 'facet' or 'endsolid', got '" + clip(t) + "'");
            facet();
        }
        cur_.restOfLine();  // the name again
    }

    void facet() {
        // "normal nx ny nz": skipped unread (some exporters write "-1.#IND00").
        const auto mark = cur_.mark();
        if (same(cur_.token(), "normal"))
            for (int k = 0; k < 3; ++k) need("a facet normal's component");
        else
            cur_.reset(mark);
        keyword("outer");
        keyword("loop");
        float v[9];
        for (int c = 0; c < 3; ++c) {
            keyword("vertex", " (a facet has 3)");
            for (int k = 0; k < 3; ++k) {
                const std::string_view t = need("a vertex coordinate");
                double x = 0;
                if (!mesh::parseDouble(t, x)) fail("expected a vertex coordinate, got '" + clip(t) + "'");
                v[3 * c + k] = float(x);
                if (const std::string problem = nonFinite(v[3 * c + k]); !problem.empty())
                    fail("facet " + std::to_string(mesh_.polygons.size()) + ": '" + clip(t) + "' is " + problem);
            }
        }
        keyword("endloop", " after 3 vertices (STL facets are triangles)");
        keyword("endfacet");
        addTriangle(mesh_, merge_, v);
    }

    mesh::TextCursor cur_;
    mesh::PolyMesh mesh_;
    VertexMerger merge_;
};

}  // namespace

std::vector<SceneObject> readStl(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "mesh");
    mesh::PolyMesh m = isAscii(data) ? AsciiStl(path, data).read() : readBinary(path, data);
    if (m.polygons.size() == 0) throw InputError(path + ": no triangles; expected an STL with at least one facet");
    return mesh::buildSceneObjects(m, std::filesystem::path(path).stem().string());
}

}  // namespace darkroom
