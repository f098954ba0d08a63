// averageVertexNormals(): angle-weighted vertex normals, split at feature
// edges, as ParaView's Generate Surface Normals (vtkPolyDataNormals with
// Splitting on) makes them. Around each vertex the triangles are grouped:
// two triangles sharing an edge at the vertex join one group unless their
// normals differ by more than the feature angle; each group becomes one
// vertex (the first keeps the original index, the others are copies added
// at the end), with the angle-weighted average of its triangles' normals.
// Angle weights (Thürmer and Wüthrich) make the result independent of how a
// polygon was cut into triangles, which area or uniform weights are not.
#include <darkroom/scene/vertex_normals.h>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <utility>

namespace darkroom {
namespace {

Vec3 position(const SceneObject& o, std::uint32_t v) {
    const float* p = &o.vertices[4 * std::size_t(v)];
    return {p[0], p[1], p[2]};
}

// The triangles around each vertex, in triangle order (so the result is
// deterministic), and each triangle's unit normal. Triangles of zero area
// (a repeated vertex, collinear corners) are left out of every fan.
struct Fans {
    std::vector<std::size_t> start;        // vertex v's triangles: [start[v], start[v + 1])
    std::vector<std::uint32_t> triangles;  // of all fans, vertex after vertex
    std::vector<std::array<float, 3>> faceNormal;  // per triangle; zero for zero area (floats: half the memory)

    std::size_t size(std::uint32_t v) const { return start[v + 1] - start[v]; }
    Vec3 face(std::size_t t) const { return {faceNormal[t][0], faceNormal[t][1], faceNormal[t][2]}; }
    bool used(std::size_t t) const { return faceNormal[t] != std::array<float, 3>{0, 0, 0}; }
};

Fans buildFans(const SceneObject& o) {
    Fans f;
    const std::size_t nt = o.indices.size() / 3, nv = o.vertexCount();
    f.faceNormal.resize(nt);
    tbb::parallel_for(std::size_t(0), nt, [&](std::size_t t) {
        const std::uint32_t* i = &o.indices[3 * t];
        const Vec3 a = position(o, i[0]);
        const Vec3 n = normalize(cross(position(o, i[1]) - a, position(o, i[2]) - a));
        const bool area = length(n) > 0.5;  // not zero, nor NaN
        f.faceNormal[t] = area ? std::array<float, 3>{float(n.x), float(n.y), float(n.z)} : std::array<float, 3>{0, 0, 0};
    });
    f.start.assign(nv + 1, 0);
    for (std::size_t t = 0; t < nt; ++t)
        if (f.used(t))
            for (int k = 0; k < 3; ++k) ++f.start[o.indices[3 * t + std::size_t(k)] + 1];
    std::partial_sum(f.start.begin(), f.start.end(), f.start.begin());
    f.triangles.resize(f.start[nv]);
    std::vector<std::size_t> next(f.start.begin(), f.start.end() - 1);
    for (std::size_t t = 0; t < nt; ++t)
        if (f.used(t))
            for (int k = 0; k < 3; ++k) f.triangles[next[o.indices[3 * t + std::size_t(k)]]++] = std::uint32_t(t);
    return f;
}

// Which of triangle t's corners is vertex v (t uses v exactly once: a
// triangle that repeats a vertex has zero area and is in no fan).
int cornerOf(const SceneObject& o, std::size_t t, std::uint32_t v) {
    return o.indices[3 * t] == v ? 0 : o.indices[3 * t + 1] == v ? 1 : 2;
}

// Fans up to this size are grouped by comparing all pairs of triangles.
constexpr std::uint32_t kSmallFan = 16;

// Buffers groupFan() reuses from one vertex to the next (a thread's own).
struct FanScratch {
    std::vector<std::uint32_t> parent, label;
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
};

// The groups of vertex v's fan: labels[i] is the group of its i-th triangle,
// numbered in order of first appearance (the group of the first triangle is
// 0). Returns the number of groups.
std::uint32_t groupFan(const SceneObject& o, const Fans& f, std::uint32_t v, double cosFeature,
                       std::uint32_t* labels, FanScratch& w) {
    const std::uint32_t m = std::uint32_t(f.size(v));
    const std::uint32_t* tris = &f.triangles[f.start[v]];
    w.parent.resize(m);
    std::iota(w.parent.begin(), w.parent.end(), 0u);
    auto root = [&](std::uint32_t i) {
        while (w.parent[i] != i) i = w.parent[i] = w.parent[w.parent[i]];
        return i;
    };
    auto join = [&](std::uint32_t i, std::uint32_t j) {
        if (dot(f.face(tris[i]), f.face(tris[j])) >= cosFeature) w.parent[root(i)] = root(j);
    };
    // Triangles that share an edge (v, x) meet where their other corner x
    // is the same: w.edges holds (x, triangle) twice per triangle.
    w.edges.clear();
    for (std::uint32_t i = 0; i < m; ++i) {
        const std::size_t t = tris[i];
        const int k = cornerOf(o, t, v);
        w.edges.push_back({o.indices[3 * t + std::size_t((k + 1) % 3)], i});
        w.edges.push_back({o.indices[3 * t + std::size_t((k + 2) % 3)], i});
    }
    if (m <= kSmallFan) {
        // Most vertices have about six triangles: comparing all pairs is
        // cheaper than sorting (measured: the grouping took twice as long).
        for (std::uint32_t i = 0; i < m; ++i)
            for (std::uint32_t j = i + 1; j < m; ++j) {
                const auto &a0 = w.edges[2 * i].first, &a1 = w.edges[2 * i + 1].first;
                const auto &b0 = w.edges[2 * j].first, &b1 = w.edges[2 * j + 1].first;
                if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) join(i, j);
            }
    } else {
        // Sorted by x, each run of one x is the triangles around one edge.
        std::sort(w.edges.begin(), w.edges.end());
        for (std::size_t a = 0; a < w.edges.size(); ++a)
            for (std::size_t b = a + 1; b < w.edges.size() && w.edges[b].first == w.edges[a].first; ++b)
                join(w.edges[a].second, w.edges[b].second);
    }
    w.label.assign(m, ~0u);
    std::uint32_t groups = 0;
    for (std::uint32_t i = 0; i < m; ++i) {
        std::uint32_t& l = w.label[root(i)];
        if (l == ~0u) l = groups++;
        labels[i] = l;
    }
    return groups;
}

// Triangle t's angle at its corner k.
double cornerAngle(const SceneObject& o, std::size_t t, int k) {
    const Vec3 p = position(o, o.indices[3 * t + std::size_t(k)]);
    const Vec3 a = position(o, o.indices[3 * t + std::size_t((k + 1) % 3)]) - p;
    const Vec3 b = position(o, o.indices[3 * t + std::size_t((k + 2) % 3)]) - p;
    // Weights need no more than float precision, and atan2f is the cheaper.
    return std::atan2(float(length(cross(a, b))), float(dot(a, b)));
}

// Split vertices: where each group's vertex goes, and what it copies.
struct Split {
    std::vector<std::uint32_t> labels;   // per fan entry (as Fans::triangles)
    std::vector<std::uint32_t> firstNew;  // per vertex: the index of its first copy
    std::vector<std::uint32_t> source;   // per copy: the vertex it copies
};

Split splitVertices(const SceneObject& o, const Fans& f, double cosFeature) {
    const std::size_t nv = o.vertexCount();
    Split s;
    s.labels.resize(f.triangles.size());
    std::vector<std::uint32_t> groups(nv, 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv), [&](const tbb::blocked_range<std::size_t>& r) {
        FanScratch w;
        for (std::size_t v = r.begin(); v < r.end(); ++v)
            if (f.size(std::uint32_t(v)) > 0)
                groups[v] = groupFan(o, f, std::uint32_t(v), cosFeature, &s.labels[f.start[v]], w);
    });
    s.firstNew.resize(nv);
    std::size_t next = nv;
    for (std::size_t v = 0; v < nv; ++v) {
        s.firstNew[v] = std::uint32_t(std::min<std::size_t>(next, 0xffffffffu));
        for (std::uint32_t g = 1; g < groups[v]; ++g) s.source.push_back(std::uint32_t(v));
        next += groups[v] > 1 ? groups[v] - 1 : 0;
    }
    return s;
}

// Vertex v's group normals into `normals` and its corners' new indices into
// `indices` (a copy of the object's: each corner belongs to one fan, so the
// threads write disjoint entries and read only the unchanged original).
void writeFan(const SceneObject& o, const Fans& f, const Split& s, std::uint32_t v, std::vector<Vec3>& sum,
              VertexNormals& normals, std::vector<std::uint32_t>& indices) {
    sum.clear();
    for (std::size_t e = f.start[v]; e < f.start[v + 1]; ++e) {
        const std::uint32_t g = s.labels[e], t = f.triangles[e];
        if (g >= sum.size()) sum.resize(g + 1, Vec3{0, 0, 0});
        sum[g] = sum[g] + f.face(t) * cornerAngle(o, t, cornerOf(o, t, v));
    }
    for (std::uint32_t g = 0; g < sum.size(); ++g) {
        const std::size_t id = g == 0 ? v : s.firstNew[v] + g - 1;
        const Vec3 n = normalize(sum[g]);
        normals[3 * id] = float(n.x), normals[3 * id + 1] = float(n.y), normals[3 * id + 2] = float(n.z);
    }
    for (std::size_t e = f.start[v]; e < f.start[v + 1]; ++e)
        if (const std::uint32_t g = s.labels[e]; g > 0) {
            const std::size_t t = f.triangles[e];
            indices[3 * t + std::size_t(cornerOf(o, t, v))] = s.firstNew[v] + g - 1;
        }
}

}  // namespace

void averageVertexNormals(SceneObject& o, double featureAngleDegrees) {
    if (o.representation != Representation::Surface) return;
    takeVertexNormals(o);
    const double pi = 3.14159265358979323846;
    // 180 degrees or more: never split, not even where rounding puts a dot
    // product of opposite normals a hair below -1.
    const double cosFeature = featureAngleDegrees >= 180 ? -2.0 : std::cos(featureAngleDegrees * pi / 180.0);
    const Fans f = buildFans(o);
    const Split s = splitVertices(o, f, cosFeature);
    const std::size_t nv = o.vertexCount(), total = nv + s.source.size();
    if (total > 0xffffffffull) return;  // the split would overflow 32-bit indices: keep the facets
    VertexNormals normals(3 * total, 0.0f);
    std::vector<std::uint32_t> indices = o.indices;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, nv), [&](const tbb::blocked_range<std::size_t>& r) {
        std::vector<Vec3> sum;
        for (std::size_t v = r.begin(); v < r.end(); ++v) writeFan(o, f, s, std::uint32_t(v), sum, normals, indices);
    });
    o.indices = std::move(indices);
    // Copies: the same position, radius and point field values.
    o.vertices.resize(4 * total);
    for (std::size_t c = 0; c < s.source.size(); ++c)
        std::copy_n(&o.vertices[4 * std::size_t(s.source[c])], 4, &o.vertices[4 * (nv + c)]);
    for (auto& field : o.fields) {
        if (field.association != ScalarField::Association::Point || field.values.size() != nv) continue;
        field.values.resize(total);
        for (std::size_t c = 0; c < s.source.size(); ++c) field.values[nv + c] = field.values[s.source[c]];
    }
    setVertexNormals(o, normals);
}

}  // namespace darkroom
