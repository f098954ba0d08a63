#include "gathers.h"

#include <darkroom/context.h>

#include <cmath>

namespace darkroom::ssdof {

namespace {

struct Offset {
    float x, y;  // unit-disc position of the spiral point
};

// Vogel's spiral: point i at radius sqrt((i + 0.5) / n) and angle i * golden
// angle covers the disc with equal area per point, so each represents pi r^2 / n.
std::vector<Offset> vogelSpiral(int n) {
    const double golden = 3.14159265358979323846 * (3.0 - std::sqrt(5.0));
    std::vector<Offset> s(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
        const double r = std::sqrt((i + 0.5) / n), a = i * golden;
        s[std::size_t(i)] = {float(r * std::cos(a)), float(r * std::sin(a))};
    }
    return s;
}

}  // namespace

void gatherDisc(const WorkImage& w, int samples, Context& ctx, GatherResult& out) {
    const std::vector<Offset> spiral = vogelSpiral(samples);
    out.colour.assign(w.colour.size(), Rgba{});
    out.unchanged.assign(w.colour.size(), 0);
    const float perSample = 1.0f / float(samples);
    ctx.parallelFor(0, w.height, 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w.width; ++x) {
                const std::size_t i = w.index(x, y);
                const float sp = w.coc[i], rp = std::fabs(sp);
                const Rgba& self = w.colour[i];

                // Near layer: spiral over the largest near CoC that can reach this tile.
                Rgba nearSum;
                float nearWeight = 0.0f;
                const float reach = w.reachAt(x, y);
                if (reach >= kInFocus) {
                    // Spiral point area over the sample's kernel area: a near
                    // region of uniform CoC = reach sums to exactly 1.
                    const float area = reach * reach * perSample;
                    for (const Offset& o : spiral) {
                        const int dx = int(std::lround(o.x * reach)), dy = int(std::lround(o.y * reach));
                        const int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= w.width || qy >= w.height) continue;
                        const std::size_t j = w.index(qx, qy);
                        const float sq = w.coc[j];
                        const float t = std::sqrt(float(dx * dx + dy * dy));
                        if (!reachesAsNear(sp, sq, t)) continue;
                        const float wq = area / (sq * sq);
                        nearSum.add(w.colour[j], wq);
                        nearWeight += wq;
                    }
                }
                if (rp < kInFocus && nearWeight == 0.0f) {
                    out.unchanged[i] = 1;
                    continue;
                }

                // Focus/far layer over the pixel's own CoC; the pixel itself
                // counts unless it is in the near field (then this layer is
                // what lies behind it).
                Rgba backSum;
                float backWeight = 0.0f;
                if (sp > -kInFocus) {
                    const float cc = std::fmax(rp, kInFocus);
                    backSum.add(self, 1.0f / (cc * cc));
                    backWeight += 1.0f / (cc * cc);
                }
                if (rp >= kInFocus)
                    for (const Offset& o : spiral) {
                        const int dx = int(std::lround(o.x * rp)), dy = int(std::lround(o.y * rp));
                        const int qx = x + dx, qy = y + dy;
                        if (qx < 0 || qy < 0 || qx >= w.width || qy >= w.height) continue;
                        const std::size_t j = w.index(qx, qy);
                        const float t = std::sqrt(float(dx * dx + dy * dy));
                        const float wq = backgroundWeight(sp, w.coc[j], t);
                        if (wq == 0.0f) continue;
                        backSum.add(w.colour[j], wq);
                        backWeight += wq;
                    }
                out.colour[i] = composite(nearSum, nearWeight, nearWeight, backSum, backWeight, self);
            }
    });
}

}  // namespace darkroom::ssdof
