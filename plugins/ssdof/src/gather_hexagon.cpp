#include "gathers.h"

#include <darkroom/context.h>

#include <algorithm>
#include <array>
#include <cmath>

namespace darkroom::ssdof {

namespace {

// A regular hexagon of circumradius n is the union of three rhombi spanned by
// pairs of the unit vectors v0, v1, v2 at 120 degrees (corners at +-v_k). A
// rhombus {a vi + b vj} is a box blur along vi followed by one along vj, so:
//   pass 1:  A  = blur along v0 over t = 0..n
//            S  = A + blur along v1 over t = 1..n
//   pass 2:  out = A(p) + sum_{t=1..n} A(p + t v1) + sum_{t=1..n} S(p + t v2)
// covers rhombus (v0,v1), rhombus (v0,v2) and rhombus (v1,v2) without its two
// edges, i.e. every lattice point of the hexagon exactly once: 3n^2 + 3n + 1
// taps from 4n + 1 reads per pass. The gather is the hexagon mirrored through
// p, which is the same hexagon. Each layer carries sums and weights through
// the passes and is normalised only at the end.
struct Partial {
    Rgba sum;
    float weight = 0.0f;
    float reach = 0.0f;  // near layer: largest CoC among the samples summed
};

struct Intermediate {
    Partial backA, backS, nearA, nearS;
};

// Lattice points of a hexagon of circumradius n: a near sample spreads weight
// 1 over its whole kernel, 1/H per tap.
float hexagonTaps(float radius) {
    const float n = std::round(radius);
    return 3.0f * n * n + 3.0f * n + 1.0f;
}

using Steps = std::vector<std::array<int, 2>>;  // rounded offsets t*v for t = 0..max

Steps steps(double angle, int count) {
    Steps s(static_cast<std::size_t>(count) + 1);
    // Image rows go down: "up" rotated clockwise by angle is (sin, -cos).
    for (int t = 0; t <= count; ++t)
        s[std::size_t(t)] = {int(std::lround(t * std::sin(angle))), int(std::lround(-t * std::cos(angle)))};
    return s;
}

bool inside(const WorkImage& w, int x, int y) { return x >= 0 && y >= 0 && x < w.width && y < w.height; }

}  // namespace

void gatherHexagon(const WorkImage& w, double rotationDegrees, Context& ctx, GatherResult& out) {
    const double pi = 3.14159265358979323846;
    float largest = 0.0f;
    for (float s : w.coc) largest = std::max(largest, std::fabs(s));
    const int maxSteps = int(std::ceil(largest)) + 1;
    std::array<Steps, 3> dir;
    for (int k = 0; k < 3; ++k) dir[std::size_t(k)] = steps((rotationDegrees + 120.0 * k) * pi / 180.0, maxSteps);

    std::vector<Intermediate> mid(w.colour.size());
    // One 1D skewed blur of both layers at pixel (x, y) along direction d over t = first..n.
    auto blur1D = [&](int x, int y, const Steps& d, int first, Partial& back, Partial& nearP) {
        const float sp = w.coc[w.index(x, y)];
        const int nBack = int(std::lround(std::fabs(sp)));
        const int nNear = int(std::lround(w.reachAt(x, y)));
        for (int t = first; t <= std::max(nBack, nNear); ++t) {
            const int qx = x + d[std::size_t(t)][0], qy = y + d[std::size_t(t)][1];
            if (!inside(w, qx, qy)) continue;
            const std::size_t j = w.index(qx, qy);
            const float sq = w.coc[j];
            if (t <= nBack) {
                const float wq = backgroundWeight(sp, sq, float(t));
                if (wq > 0.0f) {
                    back.sum.add(w.colour[j], wq);
                    back.weight += wq;
                }
            }
            if (t <= nNear && reachesAsNear(sp, sq, float(t))) {
                const float wq = 1.0f / hexagonTaps(-sq);
                nearP.sum.add(w.colour[j], wq);
                nearP.weight += wq;
                nearP.reach = std::max(nearP.reach, -sq);
            }
        }
    };

    ctx.parallelFor(0, w.height, 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w.width; ++x) {
                Intermediate& m = mid[w.index(x, y)];
                blur1D(x, y, dir[0], 0, m.backA, m.nearA);
                Partial back1, near1;
                blur1D(x, y, dir[1], 1, back1, near1);
                m.backS = m.backA;
                m.backS.sum.add(back1.sum, 1.0f);
                m.backS.weight += back1.weight;
                m.nearS = m.nearA;
                m.nearS.sum.add(near1.sum, 1.0f);
                m.nearS.weight += near1.weight;
                m.nearS.reach = std::max(m.nearS.reach, near1.reach);
            }
    });
    if (ctx.cancelled()) return;

    out.colour.assign(w.colour.size(), Rgba{});
    out.unchanged.assign(w.colour.size(), 0);
    ctx.parallelFor(0, w.height, 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w.width; ++x) {
                const std::size_t i = w.index(x, y);
                const float sp = w.coc[i], rp = std::fabs(sp);
                const Intermediate& self = mid[i];
                Rgba nearSum = self.nearA.sum;
                float nearWeight = self.nearA.weight;
                const int nNear = int(std::lround(w.reachAt(x, y)));
                for (int t = 1; t <= nNear; ++t)
                    for (int k = 1; k <= 2; ++k) {
                        const int qx = x + dir[std::size_t(k)][std::size_t(t)][0];
                        const int qy = y + dir[std::size_t(k)][std::size_t(t)][1];
                        if (!inside(w, qx, qy)) continue;
                        const Partial& q = k == 1 ? mid[w.index(qx, qy)].nearA : mid[w.index(qx, qy)].nearS;
                        if (q.weight == 0.0f || float(t) > q.reach + 0.5f) continue;
                        nearSum.add(q.sum, 1.0f);
                        nearWeight += q.weight;
                    }
                if (rp < kInFocus && nearWeight == 0.0f) {
                    out.unchanged[i] = 1;
                    continue;
                }
                Rgba backSum = self.backA.sum;
                float backWeight = self.backA.weight;
                const int nBack = int(std::lround(rp));
                for (int t = 1; t <= nBack; ++t)
                    for (int k = 1; k <= 2; ++k) {
                        const int qx = x + dir[std::size_t(k)][std::size_t(t)][0];
                        const int qy = y + dir[std::size_t(k)][std::size_t(t)][1];
                        if (!inside(w, qx, qy)) continue;
                        const std::size_t j = w.index(qx, qy);
                        // The intermediate pixel stands for its own CoC.
                        if (backgroundWeight(sp, w.coc[j], float(t)) == 0.0f) continue;
                        const Partial& q = k == 1 ? mid[j].backA : mid[j].backS;
                        backSum.add(q.sum, 1.0f);
                        backWeight += q.weight;
                    }
                out.colour[i] = composite(nearSum, nearWeight, nearWeight, backSum, backWeight, w.colour[i]);
            }
    });
}

}  // namespace darkroom::ssdof
