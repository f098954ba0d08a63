#include "mesh_checks.h"

#include <darkroom/scene/generators.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>
#include <tuple>

using namespace darkroom;
using darkroom::test::triangleCentroid;
using darkroom::test::triangleNormal;
using darkroom::test::vertexAt;

namespace {

SceneObject isosurface(const std::map<std::string, std::string>& params = {}) {
    auto objects = generate("isosurface", params);
    EXPECT_EQ(objects.size(), 1u);
    return objects.at(0);
}

using Edge = std::pair<std::uint32_t, std::uint32_t>;

std::map<Edge, int> directedEdges(const SceneObject& o) {
    std::map<Edge, int> edges;
    for (std::size_t t = 0; t < o.indices.size() / 3; ++t)
        for (int e = 0; e < 3; ++e) ++edges[{o.indices[t * 3 + e], o.indices[t * 3 + (e + 1) % 3]}];
    return edges;
}

}  // namespace

TEST(Isosurface, DefaultsGiveATriangleMeshWithFields) {
    const SceneObject o = isosurface();
    EXPECT_EQ(o.name, "isosurface");
    EXPECT_EQ(o.representation, Representation::Surface);
    ASSERT_GT(o.indices.size(), 3000u);
    EXPECT_EQ(o.indices.size() % 3, 0u);
    for (const char* name : {"height", "field", "gradient magnitude"}) {
        const ScalarField* f = o.field(name);
        ASSERT_NE(f, nullptr) << name;
        EXPECT_EQ(f->association, ScalarField::Association::Point);
        EXPECT_EQ(f->values.size(), o.vertexCount()) << name;
    }
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        EXPECT_EQ(o.field("height")->values[i], o.vertices[i * 4 + 2]);
        ASSERT_NEAR(o.field("field")->values[i], 0.5, 1e-5);
    }
}

TEST(Isosurface, IsWatertightAndConsistentlyOrientedAtAnyResolution) {
    // Coarse grids pinch and merge blobs; the mesh must stay closed regardless.
    for (const auto& [resolution, iso] : std::vector<std::pair<std::string, std::string>>{
             {"48", "0.5"}, {"7", "0.5"}, {"13", "0.2"}, {"33", "0.95"}, {"72", "0.3"}}) {
        SCOPED_TRACE("resolution " + resolution + ", isovalue " + iso);
        const SceneObject o = isosurface({{"resolution", resolution}, {"isovalue", iso}});
        ASSERT_GT(o.indices.size(), 0u);
        // Closed and oriented: every directed edge once, and its reverse once
        // (so every undirected edge is shared by exactly two triangles).
        const auto edges = directedEdges(o);
        for (const auto& [edge, count] : edges) {
            ASSERT_EQ(count, 1);
            ASSERT_EQ(edges.count({edge.second, edge.first}), 1u) << "open edge " << edge.first << "-" << edge.second;
        }
        for (std::size_t t = 0; t < o.indices.size() / 3; ++t) {
            const auto a = o.indices[t * 3], b = o.indices[t * 3 + 1], c = o.indices[t * 3 + 2];
            ASSERT_TRUE(a != b && b != c && a != c) << "degenerate triangle " << t;
            ASSERT_LT(std::max({a, b, c}), o.vertexCount());
        }
    }
}

TEST(Isosurface, VerticesAreWeldedAndUsed) {
    const SceneObject o = isosurface();
    std::set<std::tuple<float, float, float>> positions;
    for (std::size_t i = 0; i < o.vertexCount(); ++i)
        positions.insert({o.vertices[i * 4], o.vertices[i * 4 + 1], o.vertices[i * 4 + 2]});
    EXPECT_EQ(positions.size(), o.vertexCount()) << "duplicate vertices";
    std::vector<bool> used(o.vertexCount());
    for (auto i : o.indices) used[i] = true;
    EXPECT_TRUE(std::all_of(used.begin(), used.end(), [](bool u) { return u; }));
}

TEST(Isosurface, VerticesLieOnTheLevelSet) {
    for (const char* iso : {"0.3", "0.5", "0.8"}) {
        const SceneObject o = isosurface({{"isovalue", iso}, {"resolution", "32"}});
        ASSERT_GT(o.vertexCount(), 100u) << iso;
        const double h = 2.0 / 31;
        for (std::size_t i = 0; i < o.vertexCount(); ++i) {
            const Vec3 p = vertexAt(o, i);
            // Float storage of the position limits the accuracy, not the extraction.
            const double slack = 1e-6 * (1 + length(generators::demoFieldGradient(p)));
            ASSERT_NEAR(generators::demoField(p), std::stod(iso), std::min(slack, 1e-3 * h)) << "vertex " << i;
        }
    }
}

TEST(Isosurface, NormalsPointOutwardsDownTheGradient) {
    // Inside is f > isovalue, so outward is where f decreases: along -grad f.
    const SceneObject o = isosurface();
    std::size_t checked = 0;
    for (std::size_t t = 0; t < o.indices.size() / 3; ++t) {
        const Vec3 n = triangleNormal(o, t);
        if (length(n) < 1e-12) continue;  // slivers have no reliable direction
        const Vec3 g = generators::demoFieldGradient(triangleCentroid(o, t));
        ASSERT_LT(dot(normalize(n), normalize(g)), 0.0) << "triangle " << t << " faces inwards";
        ++checked;
    }
    EXPECT_GT(checked, o.indices.size() / 3 * 99 / 100);
}

TEST(Isosurface, TopologyIsSpheresAndOneTorus) {
    // Euler characteristic per connected component: 2 for a sphere, 0 for
    // the ring's torus. Catches holes, pinches and duplicated sheets.
    const SceneObject o = isosurface();
    std::vector<std::uint32_t> parent(o.vertexCount());
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&](std::uint32_t v) {
        while (parent[v] != v) v = parent[v] = parent[parent[v]];
        return v;
    };
    for (std::size_t t = 0; t < o.indices.size() / 3; ++t)
        for (int e = 1; e < 3; ++e) parent[root(o.indices[t * 3 + e])] = root(o.indices[t * 3]);
    std::map<std::uint32_t, long> vertices, halfEdges, faces;
    for (std::uint32_t v = 0; v < o.vertexCount(); ++v) ++vertices[root(v)];
    for (std::size_t t = 0; t < o.indices.size() / 3; ++t) {
        ++faces[root(o.indices[t * 3])];
        halfEdges[root(o.indices[t * 3])] += 3;
    }
    int spheres = 0, tori = 0;
    for (const auto& [component, v] : vertices) {
        const long euler = v - halfEdges[component] / 2 + faces[component];
        EXPECT_TRUE(euler == 2 || euler == 0) << "component with Euler characteristic " << euler;
        spheres += euler == 2;
        tori += euler == 0;
    }
    EXPECT_EQ(tori, 1);
    EXPECT_GE(spheres, 3);
}

TEST(Isosurface, ResolutionControlsDetail) {
    const auto coarse = isosurface({{"resolution", "24"}});
    const auto fine = isosurface({{"resolution", "80"}});
    EXPECT_GT(fine.indices.size(), 5 * coarse.indices.size());
}

TEST(Isosurface, IsDeterministic) {
    const auto a = isosurface({{"resolution", "40"}});
    const auto b = isosurface({{"resolution", "40"}});
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.indices, b.indices);
}
