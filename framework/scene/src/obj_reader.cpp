// Wavefront OBJ: `v` positions, `f` faces (v, v/vt, v//vn, v/vt/vn; negative
// indices count back from the last vertex; polygons fan-triangulated), `l`
// polylines and `p` points. Texture coordinates, normals, groups and materials
// are ignored: capture needs positions, and normals come from the geometry.
#include "poly_mesh.h"
#include <darkroom/data/formats/text_cursor.h>

#include <darkroom/scene/mesh_readers.h>

#include <filesystem>

namespace darkroom {
namespace {

// Resolves the vertex part of one `f`/`l`/`p` reference ("7", "7/2", "-1//3").
// Returns an empty message on success.
std::string vertexIndex(std::string_view ref, std::size_t defined, std::uint32_t& out) {
    const std::string_view v = ref.substr(0, ref.find('/'));
    long long i = 0;
    if (!mesh::parseInteger(v, i))
        return ("expected a vertex index (n, n/t, n//m or n/t/m), got '" + std::string(ref.substr(0, 40)) + "'");
    const long long n = static_cast<long long>(defined);
    if (i < 0) i = n + i + 1;  // -1 is the most recent vertex
    if (i < 1 || i > n)
        return ("vertex index " + std::string(v) + " out of range: " + std::to_string(n) +
                 " vertices defined so far (expected 1.." + std::to_string(n) + " or -1..-" + std::to_string(n) + ")");
    out = static_cast<std::uint32_t>(i - 1);
    return {};
}

}  // namespace

std::vector<SceneObject> readObj(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "mesh");
    mesh::TextCursor cur(path, data);
    mesh::PolyMesh m;
    m.source = path;
    std::uint32_t cell = 0;
    while (!cur.atEnd()) {
        const int line = cur.line();
        const auto t = mesh::splitBlanks(cur.restOfLine());
        auto fail = [&](const std::string& what) { throw Error(path + ":" + std::to_string(line) + ": " + what); };
        if (t.empty() || t[0][0] == '#') continue;
        if (t[0] == "v") {
            if (t.size() < 4) fail("expected 'v x y z'");
            for (int k = 1; k <= 3; ++k) {
                double x = 0;
                if (!mesh::parseDouble(t[std::size_t(k)], x))
                    fail("expected a number for vertex coordinate, got '" + std::string(t[std::size_t(k)].substr(0, 40)) + "'");
                m.points.push_back(float(x));
            }
        } else if (t[0] == "f" || t[0] == "l" || t[0] == "p") {
            mesh::CellList& list = t[0] == "f" ? m.polygons : t[0] == "l" ? m.lines : m.vertices;
            const std::size_t need = t[0] == "f" ? 3 : t[0] == "l" ? 2 : 1;
            if (t.size() < need + 1) fail("'" + std::string(t[0]) + "' needs at least " + std::to_string(need) + " vertices");
            for (std::size_t k = 1; k < t.size(); ++k) {
                std::uint32_t index = 0;
                const std::string problem = vertexIndex(t[k], m.pointCount(), index);
                if (!problem.empty()) fail(problem);
                list.connectivity.push_back(index);
            }
            list.close(cell++);
        }
        // vt, vn, vp, o, g, s, usemtl, mtllib: not needed for capture.
    }
    m.cellCount = cell;
    // Faces cannot exist without vertices, so this is the empty file too.
    if (m.points.empty())
        throw InputError(path + ": no vertices ('v x y z' lines); expected an OBJ mesh with at least one vertex");
    // OBJ's VTK-style order (vertices, lines, polygons) does not matter: no cell data.
    return mesh::buildSceneObjects(m, std::filesystem::path(path).stem().string());
}

}  // namespace darkroom
