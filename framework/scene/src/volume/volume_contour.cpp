// Isosurfaces and slices of a volume by marching tetrahedra. Each cell is
// split into tetrahedra: a tetrahedron is one; a pyramid is two, split across
// its base; wedges and hexahedra get a point at their centroid (value: the
// mean of the corners) and one tetrahedron per face triangle. Quadrilateral
// faces are always split through their corner with the smallest point id, so
// the two cells sharing a face split it the same way and the surface has no
// cracks. Cut-edge vertices are shared through a hash of the edge's two point
// ids, so the surface is welded; every point array is interpolated along the
// edge with the same parameter as the position.
#include "cell_topology.h"
#include "volume_gradient.h"
#include "volume_polymesh.h"

#include <darkroom/scene/vertex_normals.h>

#include <darkroom/error.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>

namespace darkroom::volume {
namespace {

struct Corner {
    std::uint64_t id;  // volume point id, or pointCount + cell for a centroid
    Vec3 p;
    double s;  // the scalar being contoured
};

struct CutVertex {
    std::uint64_t a, b;  // ends, a < b
    float t;             // position = a + t (b - a)
    std::uint32_t cell;  // the cell whose centroid an end may be
};

class Contour {
public:
    Contour(const VolumeMesh& v, mesh::PolyMesh& out) : v_(v), out_(out), np_(v.pointCount()) {}

    // One surface: scalar(point) == level. `flip` reverses the triangles.
    void run(const std::vector<float>& scalar, double level, bool flip) {
        scalar_ = &scalar;
        level_ = level;
        flip_ = flip;
        edges_.clear();
        std::vector<std::uint32_t> ids;
        const std::size_t n = v_.cellCount();
        for (std::size_t c = 0; c < n; ++c) {
            const int type = v_.cell(c, ids);
            if (!isVolumeCell(type)) continue;
            toLinearCorners(type, ids);
            double lo = scalar[ids[0]], hi = lo;
            for (auto id : ids) lo = std::min(lo, double(scalar[id])), hi = std::max(hi, double(scalar[id]));
            if (!(lo <= level) || !(hi > level)) continue;  // all on one side (NaN: skipped)
            cell(std::uint32_t(c), linearCell(type).type, ids);
        }
    }

    // Point arrays at the cut vertices, once every surface has been run.
    void interpolateArrays() {
        for (const auto& a : v_.pointData) out_.pointData.push_back(interpolate(a.name, a.components, a.values));
    }

    // The volume points interpolate() reads: the ends of the cut edges, and
    // the corners of a cell whose centroid is an end.
    std::vector<std::uint8_t> pointsRead() const {
        std::vector<std::uint8_t> read(np_, 0);
        std::vector<std::uint32_t> ids;
        for (const CutVertex& cv : cuts_) {
            if (cv.a < np_) read[cv.a] = 1;
            if (cv.b < np_) {
                read[cv.b] = 1;
                continue;
            }
            const int type = v_.cell(cv.cell, ids);
            toLinearCorners(type, ids);
            for (auto id : ids) read[id] = 1;
        }
        return read;
    }

    // A point array (`components` values per volume point) at the cut
    // vertices, with the parameter of each vertex's position along its edge;
    // at a cell's centroid, the mean of the cell's corners.
    mesh::DataArray interpolate(const std::string& name, int components, const std::vector<float>& values) const {
        std::vector<std::uint32_t> ids;
        const std::size_t nc = std::size_t(components);
        mesh::DataArray d{name, components, std::vector<float>(cuts_.size() * nc)};
        std::vector<double> centroid(nc);
        for (std::size_t i = 0; i < cuts_.size(); ++i) {
            const CutVertex& cv = cuts_[i];
            // Only one end can be a cell's centroid (ids past the points), and only b, or a == b.
            if (cv.b >= np_) {
                const int type = v_.cell(cv.cell, ids);
                toLinearCorners(type, ids);
                std::fill(centroid.begin(), centroid.end(), 0.0);
                for (auto id : ids)
                    for (std::size_t k = 0; k < nc; ++k) centroid[k] += values[std::size_t(id) * nc + k];
                for (auto& x : centroid) x /= double(ids.size());
            }
            for (std::size_t k = 0; k < nc; ++k) {
                const double vb = cv.b >= np_ ? centroid[k] : values[std::size_t(cv.b) * nc + k];
                const double va = cv.a >= np_ ? centroid[k] : values[std::size_t(cv.a) * nc + k];
                d.values[i * nc + k] = float(va + double(cv.t) * (vb - va));
            }
        }
        return d;
    }

private:
    Corner corner(std::uint32_t id) const { return {id, v_.point(id), double((*scalar_)[id])}; }

    // Splits a quad (a, b, c, d) through its corner with the smallest point id.
    static void splitQuad(const std::array<int, 4>& q, const std::vector<Corner>& k,
                          std::vector<std::array<int, 3>>& tris) {
        int m = 0;
        for (int i = 1; i < 4; ++i)
            if (k[std::size_t(q[std::size_t(i)])].id < k[std::size_t(q[std::size_t(m)])].id) m = i;
        const int a = q[std::size_t(m)], b = q[std::size_t((m + 1) % 4)], c = q[std::size_t((m + 2) % 4)],
                  d = q[std::size_t((m + 3) % 4)];
        tris.push_back({a, b, c});
        tris.push_back({a, c, d});
    }

    void cell(std::uint32_t c, int linearType, const std::vector<std::uint32_t>& ids) {
        std::vector<Corner> k;
        for (auto id : ids) k.push_back(corner(id));
        std::vector<std::array<int, 4>> tets;
        if (linearType == kTetra) {
            tets.push_back({0, 1, 2, 3});
        } else if (linearType == kPyramid) {
            std::vector<std::array<int, 3>> base;
            splitQuad({0, 1, 2, 3}, k, base);
            for (const auto& t : base) tets.push_back({t[0], t[1], t[2], 4});
        } else {
            Corner centroid{np_ + c, {0, 0, 0}, 0};
            for (const auto& x : k) centroid.p = centroid.p + x.p, centroid.s += x.s;
            centroid.p = centroid.p * (1.0 / double(k.size()));
            centroid.s /= double(k.size());
            const int s = int(k.size());
            k.push_back(centroid);
            std::vector<std::array<int, 3>> tris;
            for (const Face& f : facesOf(linearType)) {
                if (f.count == 3) tris.push_back({f.corner[0], f.corner[1], f.corner[2]});
                else splitQuad(f.corner, k, tris);
            }
            for (const auto& t : tris) tets.push_back({t[0], t[1], t[2], s});
        }
        for (const auto& t : tets) tetrahedron(c, k, t);
    }

    std::uint32_t cut(std::uint32_t cell, const Corner& x, const Corner& y) {
        // An end exactly on the level is the vertex itself, shared by all its edges
        // (several coincident vertices would make zero-area triangles).
        const Corner* on = x.s == level_ ? &x : y.s == level_ ? &y : nullptr;
        const Corner& a = on ? *on : x.id < y.id ? x : y;
        const Corner& b = on ? *on : x.id < y.id ? y : x;
        const std::uint64_t key = (a.id << 32) | b.id;
        const auto [it, fresh] = edges_.try_emplace(key, std::uint32_t(cuts_.size()));
        if (!fresh) return it->second;
        // Parameter from the smaller id, so both cells sharing the edge agree exactly.
        const double t = on ? 0.0 : (level_ - a.s) / (b.s - a.s);
        const Vec3 p = a.p + (b.p - a.p) * t;
        out_.points.insert(out_.points.end(), {float(p.x), float(p.y), float(p.z)});
        cuts_.push_back({a.id, b.id, float(t), cell});
        return it->second;
    }

    void triangle(std::uint32_t cell, std::uint32_t p, std::uint32_t q, std::uint32_t r, const Vec3& towardsLow) {
        if (p == q || q == r || p == r) return;  // collapsed onto a vertex on the level
        auto at = [&](std::uint32_t i) { return Vec3{out_.points[3 * i], out_.points[3 * i + 1], out_.points[3 * i + 2]}; };
        const Vec3 n = cross(at(q) - at(p), at(r) - at(p));
        // Normals point from the high side (s > level) to the low side; slices flip that.
        if ((dot(n, towardsLow) < 0) != flip_) std::swap(q, r);
        out_.polygons.connectivity.insert(out_.polygons.connectivity.end(), {p, q, r});
        out_.polygons.close(cell);
    }

    void tetrahedron(std::uint32_t cell, const std::vector<Corner>& k, const std::array<int, 4>& t) {
        std::array<const Corner*, 4> high{}, low{};
        int nh = 0, nl = 0;
        for (int i : t) {
            const Corner& x = k[std::size_t(i)];
            if (x.s > level_) high[std::size_t(nh++)] = &x;
            else low[std::size_t(nl++)] = &x;
        }
        if (nh == 0 || nl == 0) return;
        Vec3 ch{0, 0, 0}, cl{0, 0, 0};
        for (int i = 0; i < nh; ++i) ch = ch + high[std::size_t(i)]->p;
        for (int i = 0; i < nl; ++i) cl = cl + low[std::size_t(i)]->p;
        const Vec3 towardsLow = cl * (1.0 / nl) - ch * (1.0 / nh);
        if (nh == 1 || nl == 1) {
            // One corner alone on its side: a triangle around it.
            const Corner* lone = nh == 1 ? high[0] : low[0];
            const auto& others = nh == 1 ? low : high;
            triangle(cell, cut(cell, *lone, *others[0]), cut(cell, *lone, *others[1]), cut(cell, *lone, *others[2]),
                     towardsLow);
            return;
        }
        // Two and two: the cut is a quadrilateral ac, ad, bd, bc.
        const Corner &a = *high[0], &b = *high[1], &c = *low[0], &d = *low[1];
        const std::uint32_t ac = cut(cell, a, c), ad = cut(cell, a, d), bd = cut(cell, b, d), bc = cut(cell, b, c);
        triangle(cell, ac, ad, bd, towardsLow);
        triangle(cell, ac, bd, bc, towardsLow);
    }

    const VolumeMesh& v_;
    mesh::PolyMesh& out_;
    const std::uint64_t np_;
    const std::vector<float>* scalar_ = nullptr;
    double level_ = 0;
    bool flip_ = false;
    std::unordered_map<std::uint64_t, std::uint32_t> edges_;
    std::vector<CutVertex> cuts_;
};

// The shading normals of an isosurface: the field's gradient interpolated
// to each vertex, reversed (the surface's normals point from high to low
// values), as the point fields N.x, N.y, N.z (vertex_normals.h).
void gradientNormals(const Contour& contour, const std::vector<float>& gradient, mesh::PolyMesh& out) {
    const mesh::DataArray g = contour.interpolate("gradient", 3, gradient);
    const std::size_t n = g.values.size() / 3;
    std::array<mesh::DataArray, 3> normal;
    for (int a = 0; a < 3; ++a) normal[std::size_t(a)] = {kVertexNormalFields[a], 1, std::vector<float>(n)};
    for (std::size_t i = 0; i < n; ++i) {
        const Vec3 d = normalize(Vec3{g.values[3 * i], g.values[3 * i + 1], g.values[3 * i + 2]}) * -1.0;
        normal[0].values[i] = float(d.x), normal[1].values[i] = float(d.y), normal[2].values[i] = float(d.z);
    }
    for (auto& component : normal) out.pointData.push_back(std::move(component));
}

}  // namespace

void buildContour(const VolumeMesh& v, const VolumeRepresentation& r, mesh::PolyMesh& out) {
    Contour contour(v, out);
    const std::size_t np = v.pointCount();
    if (r.kind == VolumeRepresentation::Kind::Isosurface) {
        const VolumeArray* f = nullptr;
        for (const auto& a : v.pointData)
            if (a.name == r.contourBy) f = &a;
        if (!f || f->components != 1) throw Error(v.source + ": internal: contour field missing");
        for (double level : r.isovalues) contour.run(f->values, level, false);
        contour.interpolateArrays();
        if (r.gradientNormals) gradientNormals(contour, pointGradient(v, f->values, contour.pointsRead()), out);
        return;
    }
    std::vector<float> distance(np);
    for (const SlicePlane& plane : r.planes) {
        const double len = length(plane.normal);
        if (!(len > 0)) throw Error(v.source + ": a slice plane's normal must not be zero");
        const Vec3 n = plane.normal * (1.0 / len);
        for (std::size_t i = 0; i < np; ++i) distance[i] = float(dot(v.point(i) - plane.origin, n));
        contour.run(distance, 0.0, true);
    }
    contour.interpolateArrays();
}

}  // namespace darkroom::volume
