#include <darkroom/scene/marching_tetrahedra.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace darkroom::generators {
namespace {

// Cube corner c has offset (c & 1, c >> 1 & 1, c >> 2 & 1).
Vec3 cornerOffset(int c) { return {double(c & 1), double(c >> 1 & 1), double(c >> 2 & 1)}; }

// The six Kuhn tetrahedra: paths 0 -> a -> a|b -> 7 for each axis order,
// each stored positively oriented (det(v1-v0, v2-v0, v3-v0) > 0) so that
// the orientation rules below hold.
std::array<std::array<int, 4>, 6> makeKuhnTetrahedra() {
    std::array<std::array<int, 4>, 6> tets{};
    std::array<int, 3> axes{1, 2, 4};
    int n = 0;
    do {
        std::array<int, 4> t{0, axes[0], axes[0] | axes[1], 7};
        const Vec3 o = cornerOffset(t[0]);
        const double det = dot(cross(cornerOffset(t[1]) - o, cornerOffset(t[2]) - o), cornerOffset(t[3]) - o);
        if (det < 0) std::swap(t[2], t[3]);
        tets[n++] = t;
    } while (std::next_permutation(axes.begin(), axes.end()));
    return tets;
}

bool oddPermutation(const std::array<int, 4>& p) {
    int inversions = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) inversions += p[i] > p[j];
    return inversions % 2 != 0;
}

class Extractor {
public:
    Extractor(const std::function<double(const Vec3&)>& f, const LevelSetGrid& grid, double iso, bool refine)
        : f_(f), grid_(grid), n_(grid.samples), iso_(iso), refine_(refine),
          step_{(grid.hi.x - grid.lo.x) / (n_ - 1), (grid.hi.y - grid.lo.y) / (n_ - 1),
                (grid.hi.z - grid.lo.z) / (n_ - 1)} {
        const std::size_t plane = std::size_t(n_) * n_;
        for (auto& s : values_) s.resize(plane);
        for (auto& e : inPlane_) e.assign(plane * 3, -1);
        across_.assign(plane * 4, -1);
    }

    LevelSetMesh run() {
        sampleSlice(0);
        for (int k = 0; k + 1 < n_; ++k) {
            sampleSlice(k + 1);
            std::fill(inPlane_[(k + 1) % 2].begin(), inPlane_[(k + 1) % 2].end(), -1);
            std::fill(across_.begin(), across_.end(), -1);
            for (int j = 0; j + 1 < n_; ++j)
                for (int i = 0; i + 1 < n_; ++i) cube(i, j, k);
        }
        return std::move(mesh_);
    }

private:
    Vec3 point(int i, int j, int k) const {
        return {grid_.lo.x + i * step_.x, grid_.lo.y + j * step_.y, grid_.lo.z + k * step_.z};
    }

    void sampleSlice(int k) {
        std::vector<double>& v = values_[k % 2];
        // Values never equal the isovalue exactly: a vertex would then sit on a
        // grid point shared by several edges, giving zero-area triangles.
        const double nudge = 1e-9 * std::max(1.0, std::abs(iso_));
        tbb::parallel_for(0, n_, [&](int j) {
            for (int i = 0; i < n_; ++i) {
                double x = f_(point(i, j, k));
                if (x <= iso_ && x > iso_ - nudge) x = iso_ - nudge;
                v[std::size_t(j) * n_ + i] = x;
            }
        });
    }

    double value(int i, int j, int k) const { return values_[k % 2][std::size_t(j) * n_ + i]; }

    // Vertex on the tetrahedron edge between cube corners ca and cb of cube (i, j, k).
    std::uint32_t edgeVertex(int i, int j, int k, int ca, int cb) {
        const int lowCorner = ca & cb;  // Kuhn edges join a corner to a superset corner
        const int d = ca ^ cb;
        const int li = i + (lowCorner & 1), lj = j + (lowCorner >> 1 & 1), lk = k + (lowCorner >> 2 & 1);
        const std::size_t cell = std::size_t(lj) * n_ + li;
        int& slot = (d & 4) ? across_[cell * 4 + (d - 4)] : inPlane_[lk % 2][cell * 3 + (d - 1)];
        if (slot >= 0) return std::uint32_t(slot);
        const int hi = li + (d & 1), hj = lj + (d >> 1 & 1), hk = lk + (d >> 2 & 1);
        slot = int(mesh_.positions.size());
        mesh_.positions.push_back(crossing(point(li, lj, lk), value(li, lj, lk), point(hi, hj, hk), value(hi, hj, hk)));
        return std::uint32_t(slot);
    }

    Vec3 crossing(Vec3 a, double fa, Vec3 b, double fb) const {
        double ta = 0, tb = 1;
        double t = (iso_ - fa) / (fb - fa);
        if (refine_) {
            // Illinois regula falsi on [ta, tb]; the bracket keeps the vertex
            // on its edge, so refinement cannot change the topology.
            fa -= iso_;
            fb -= iso_;
            int side = 0;
            for (int it = 0; it < 60 && tb - ta > 1e-13; ++it) {
                t = (ta * fb - tb * fa) / (fb - fa);
                const double ft = f_(a + (b - a) * t) - iso_;
                if (std::abs(ft) < 1e-12) break;
                if ((ft > 0) == (fa > 0)) {
                    ta = t, fa = ft;
                    if (side == -1) fb *= 0.5;
                    side = -1;
                } else {
                    tb = t, fb = ft;
                    if (side == 1) fa *= 0.5;
                    side = 1;
                }
            }
        }
        return a + (b - a) * t;
    }

    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mesh_.triangles.insert(mesh_.triangles.end(), {a, b, c});
    }

    void cube(int i, int j, int k) {
        std::array<double, 8> v{};
        int insideMask = 0;
        for (int c = 0; c < 8; ++c) {
            v[c] = value(i + (c & 1), j + (c >> 1 & 1), k + (c >> 2 & 1));
            if (v[c] > iso_) insideMask |= 1 << c;
        }
        if (insideMask == 0 || insideMask == 0xff) return;
        static const auto tets = makeKuhnTetrahedra();
        for (const auto& tet : tets) {
            // Order tet positions as [inside..., outside...]; the orientation
            // rules below need an even permutation of the positive tetrahedron,
            // so an odd one is fixed by swapping the last two (same side).
            std::array<int, 4> order{};
            int inCount = 0, n = 0;
            for (int p = 0; p < 4; ++p)
                if (insideMask >> tet[p] & 1) order[n++] = p, ++inCount;
            if (inCount == 0 || inCount == 4) continue;
            for (int p = 0; p < 4; ++p)
                if (!(insideMask >> tet[p] & 1)) order[n++] = p;
            if (inCount == 3) std::rotate(order.begin(), order.begin() + 3, order.end());  // [out, in, in, in]
            if (oddPermutation(order)) std::swap(order[2], order[3]);
            const int a = tet[order[0]], b = tet[order[1]], c = tet[order[2]], d = tet[order[3]];
            auto e = [&](int p, int q) { return edgeVertex(i, j, k, p, q); };
            if (inCount == 1) {
                // Homothetic to the face (b, c, d), whose normal points away from a.
                triangle(e(a, b), e(a, c), e(a, d));
            } else if (inCount == 3) {
                // a is the outside corner: the face normal must point towards it.
                triangle(e(a, b), e(a, d), e(a, c));
            } else {
                const std::uint32_t ac = e(a, c), ad = e(a, d), bd = e(b, d), bc = e(b, c);
                triangle(ac, ad, bd);
                triangle(ac, bd, bc);
            }
        }
    }

    const std::function<double(const Vec3&)>& f_;
    LevelSetGrid grid_;
    int n_;
    double iso_;
    bool refine_;
    Vec3 step_;
    std::array<std::vector<double>, 2> values_;
    std::array<std::vector<int>, 2> inPlane_;  // per slice: edges along +x, +y, +x+y
    std::vector<int> across_;                  // current layer: edges with a +z step
    LevelSetMesh mesh_;
};

}  // namespace

LevelSetMesh extractLevelSet(const std::function<double(const Vec3&)>& f, const LevelSetGrid& grid,
                             double isovalue, bool refine) {
    return Extractor(f, grid, isovalue, refine).run();
}

}  // namespace darkroom::generators
