// Object File Format (Geomview's OFF, as geometry-processing tools and data
// sets such as ModelNet and the Princeton Shape Benchmark write it), ASCII:
// a keyword [ST][C][N]OFF, the counts "vertices faces [edges]" (on the
// keyword's line, even glued to it as in "OFF490 518 0", or on the next),
// one vertex a line and one face a line ("n i0 ... i(n-1)", 0-based, fan-
// triangulated like OBJ and PLY polygons). Normals (N), colours (C) and
// texture coordinates (ST) after a vertex's x y z and a colour after a face's
// indices are ignored: capture computes normals from the geometry and colours by
// fields. '#' starts a comment anywhere. Lines matter: only the line's end
// tells a face's colour from its indices.
#include "poly_mesh.h"
#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/limits.h>
#include <darkroom/scene/mesh_readers.h>

#include <cmath>
#include <cstdint>
#include <filesystem>

namespace darkroom {
namespace {

// Least bytes a vertex line ("0 0 0\n") and a face line ("3 0 0 0\n") take:
// the counts are checked against the rest of the file before anything is
// allocated for them (the file's last line may lack its newline).
constexpr std::uint64_t kLeastVertexBytes = 6, kLeastFaceBytes = 8;
// Values a face line may carry after its indices: a colour-map index, RGB or RGBA.
constexpr std::size_t kMostFaceColourValues = 4;

std::string clip(std::string_view s) { return std::string(s.substr(0, 40)); }

class OffReader {
public:
    OffReader(const std::string& path, std::string_view data) : path_(path), cur_(path, data) {}

    mesh::PolyMesh read() {
        mesh_.source = path_;
        readHeader();
        readVertices();
        readFaces();
        const Line extra = next();
        if (!extra.tokens.empty())
            fail(extra.number, "unexpected '" + clip(extra.tokens[0]) + "' after the " + std::to_string(faceCount_) +
                                   " faces declared on line " + std::to_string(countsLine_) +
                                   "; expected the end of the file (are the counts right?)");
        return std::move(mesh_);
    }

private:
    struct Line {
        int number = 0;
        std::vector<std::string_view> tokens;  // empty: end of file
    };

    [[noreturn]] void fail(int line, const std::string& what) const {
        throw InputError(path_ + ":" + std::to_string(line) + ": " + what);
    }

    // The next line with content, its comment removed.
    Line next() {
        while (!cur_.atEnd()) {
            const int line = cur_.line();
            std::string_view text = cur_.restOfLine();
            text = text.substr(0, text.find('#'));
            auto tokens = mesh::splitBlanks(text);
            if (!tokens.empty()) return {line, std::move(tokens)};
        }
        return {cur_.line(), {}};
    }

    void readHeader() {
        Line l = next();
        const char* keywords = "'OFF', 'COFF', 'NOFF', 'CNOFF' or 'STOFF'";
        if (l.tokens.empty())
            throw InputError(path_ + ": empty file; expected an OFF header (" + keywords + ") and the counts");
        const std::string_view key = l.tokens[0];
        std::size_t at = 0;
        auto prefix = [&](std::string_view p) {
            if (key.substr(at, p.size()) != p) return false;
            at += p.size();
            return true;
        };
        // Geomview's order: [ST][C][N][4][n]OFF.
        prefix("ST");
        prefix("C");
        normals_ = prefix("N");
        const bool fourD = prefix("4"), nD = prefix("n");
        if (!prefix("OFF")) fail(l.number, "expected an OFF header (" + std::string(keywords) + "), got '" + clip(key) + "'");
        if (fourD || nD)
            fail(l.number, "'" + clip(key) + "': 4D and n-dimensional OFF are not supported; expected 3D vertices (" +
                               keywords + ")");
        std::vector<std::string_view> counts;
        if (at < key.size()) counts.push_back(key.substr(at));  // "OFF490 518 0"
        counts.insert(counts.end(), l.tokens.begin() + 1, l.tokens.end());
        if (!counts.empty() && counts[0] == "BINARY")
            fail(l.number, "binary OFF ('OFF BINARY') is not supported; expected ASCII OFF (meshio or MeshLab convert it)");
        if (counts.empty()) {
            l = next();
            if (l.tokens.empty()) fail(l.number, "unexpected end of file; expected the counts 'vertices faces edges'");
            counts = l.tokens;
        }
        readCounts(counts, l.number);
    }

    void readCounts(const std::vector<std::string_view>& t, int line) {
        const std::string expected = "expected the counts 'vertices faces edges' (edges optional)";
        if (t.size() < 2 || t.size() > 3) fail(line, expected + ", got " + std::to_string(t.size()) + " values");
        long long c[3] = {0, 0, 0};
        for (std::size_t i = 0; i < t.size(); ++i)
            if (!mesh::parseInteger(t[i], c[i])) fail(line, expected + ", got '" + clip(t[i]) + "'");
        if (c[0] < 0 || c[1] < 0 || c[2] < 0) fail(line, "a negative count; " + expected + ", each 0 or more");
        if (c[0] == 0) fail(line, "no vertices; expected an OFF mesh with at least one vertex");
        // The edge count is informational: OFF lists no edges.
        const std::uint64_t room = cur_.remaining() + 1, nv = std::uint64_t(c[0]), nf = std::uint64_t(c[1]);
        if (nv > room / kLeastVertexBytes || nf > room / kLeastFaceBytes ||
            nv * kLeastVertexBytes + nf * kLeastFaceBytes > room || nv > 0xffffffffu)
            fail(line, "declares " + std::to_string(nv) + " vertices and " + std::to_string(nf) + " faces, but the " +
                           std::to_string(cur_.remaining()) + " bytes left in the file cannot hold them (a vertex line "
                           "takes 6 bytes at least, a face line 8; truncated?)");
        checkBytes(Limit::DecodedBytes, nv * 12, path_, std::to_string(nv) + " OFF vertices");
        vertexCount_ = nv;
        faceCount_ = nf;
        countsLine_ = line;
    }

    std::string truncated(std::size_t done, std::size_t of, const char* what, const char* form) const {
        return "unexpected end of file after " + std::to_string(done) + " of the " + std::to_string(of) + " " + what +
               " declared on line " + std::to_string(countsLine_) + "; expected '" + form + "' (truncated?)";
    }

    void readVertices() {
        const std::size_t need = normals_ ? 6 : 3;
        const char* form = normals_ ? "x y z nx ny nz" : "x y z";
        mesh_.points.reserve(vertexCount_ * 3);
        for (std::size_t i = 0; i < vertexCount_; ++i) {
            const Line l = next();
            if (l.tokens.empty()) fail(l.number, truncated(i, vertexCount_, "vertices", form));
            // The message is built only on failure: this runs for every vertex.
            auto bad = [&](const std::string& what) { fail(l.number, "vertex " + std::to_string(i) + ": " + what); };
            if (l.tokens.size() < need) bad("expected '" + std::string(form) + "', got " + std::to_string(l.tokens.size()) + " values");
            for (std::size_t k = 0; k < need; ++k) {
                double v = 0;
                if (!mesh::parseDouble(l.tokens[k], v)) bad("expected a number, got '" + clip(l.tokens[k]) + "'");
                if (k >= 3) continue;  // the normal: checked as a number, not kept
                // Points are float32: 1e39 is as unusable as inf (and as NaN: the bounds and the cameras).
                if (!std::isfinite(float(v)))
                    bad("coordinate '" + clip(l.tokens[k]) + "' is not a finite float32; expected finite coordinates");
                mesh_.points.push_back(float(v));
            }
        }
    }

    void readFaces() {
        for (std::size_t i = 0; i < faceCount_; ++i) {
            const Line l = next();
            if (l.tokens.empty()) fail(l.number, truncated(i, faceCount_, "faces", "n i0 i1 ... i(n-1)"));
            readFace(l, i);
            mesh_.polygons.close(static_cast<std::uint32_t>(i));
        }
        mesh_.cellCount = faceCount_;
    }

    void readFace(const Line& l, std::size_t i) {
        auto bad = [&](const std::string& what) { fail(l.number, "face " + std::to_string(i) + ": " + what); };
        long long n = 0;
        if (!mesh::parseInteger(l.tokens[0], n)) bad("expected the face's vertex count, got '" + clip(l.tokens[0]) + "'");
        if (n < 3) bad("a face needs at least 3 vertices, got " + std::to_string(n));
        const std::size_t indices = l.tokens.size() - 1;
        if (std::uint64_t(n) > indices)
            bad("declares " + std::to_string(n) + " vertices but the line holds only " + std::to_string(indices) +
                " values; expected " + std::to_string(n) + " vertex indices");
        if (indices - std::size_t(n) > kMostFaceColourValues)
            bad(std::to_string(indices - std::size_t(n)) + " values after its " + std::to_string(n) +
                " vertex indices; expected at most 4 (a colour; is the vertex count right?)");
        for (std::size_t k = 1; k <= std::size_t(n); ++k) {
            long long v = 0;
            if (!mesh::parseInteger(l.tokens[k], v)) bad("expected a vertex index, got '" + clip(l.tokens[k]) + "'");
            if (v < 0 || std::uint64_t(v) >= vertexCount_)
                bad("vertex index " + std::to_string(v) + " out of range; expected 0 to " +
                    std::to_string(static_cast<long long>(vertexCount_) - 1) + " (" + std::to_string(vertexCount_) +
                    " vertices declared on line " + std::to_string(countsLine_) + ")");
            mesh_.polygons.connectivity.push_back(static_cast<std::uint32_t>(v));
        }
    }

    std::string path_;
    mesh::TextCursor cur_;
    bool normals_ = false;
    std::size_t vertexCount_ = 0, faceCount_ = 0;
    int countsLine_ = 0;
    mesh::PolyMesh mesh_;
};

}  // namespace

std::vector<SceneObject> readOff(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "mesh");
    OffReader reader(path, data);
    return mesh::buildSceneObjects(reader.read(), std::filesystem::path(path).stem().string());
}

}  // namespace darkroom
