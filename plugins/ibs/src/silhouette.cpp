#include "silhouette.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::passes {

namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

bool hasData(float z) { return !std::isnan(z) && z != -kInf; }

// True when p is the near pixel of a discontinuity between p and q.
bool nearOfEdge(float zp, float zq, std::uint32_t ip, std::uint32_t iq, bool useIds, double threshold) {
    if (zp == kInf) return false;  // background is never in front
    if (zq == kInf) return true;
    if (zp > zq) return false;
    if (double(zq) - double(zp) > threshold * std::abs(double(zp))) return true;
    return useIds && ip != iq && (zp < zq || ip < iq);
}

}  // namespace

void silhouetteAt(const SilhouetteJob& job, int x, int y) {
    const int w = job.width, h = job.height;
    const std::size_t i = std::size_t(y) * w + x;
    job.out[i] = 0.0f;
    const float zp = job.depth[i];
    if (!hasData(zp)) return;
    const bool useIds = job.ids != nullptr;
    const std::uint32_t ip = useIds ? job.ids[i] : 0;
    for (const auto& [dx, dy] : job.disk) {
        const int qx = x + dx, qy = y + dy;
        if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
        const std::size_t j = std::size_t(qy) * w + qx;
        const float zq = job.depth[j];
        if (!hasData(zq)) continue;
        const std::uint32_t iq = useIds ? job.ids[j] : 0;
        const bool edge = job.nearSide ? nearOfEdge(zp, zq, ip, iq, useIds, job.threshold)
                                       : nearOfEdge(zq, zp, iq, ip, useIds, job.threshold);
        if (edge) {
            job.out[i] = 1.0f;
            return;
        }
    }
}

void silhouette(Context& ctx, const float* depth, const std::uint32_t* ids, int w, int h,
                const SilhouetteOptions& o, float* out) {
    SilhouetteJob job{depth, ids, w, h, {}, 0, o.depthThreshold, o.nearSide, out};
    // Disk of offsets, nearest first so most edge pixels stop early.
    const int r = int(std::floor(o.width + 1e-9));
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
            if ((dx || dy) && dx * dx + dy * dy <= o.width * o.width + 1e-9) {
                job.disk.emplace_back(dx, dy);
                job.radius = std::max(job.radius, std::abs(dx));
            }
    std::stable_sort(job.disk.begin(), job.disk.end(), [](const auto& a, const auto& b) {
        return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second;
    });
    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const int left = std::min(job.radius, w), right = std::max(left, w - job.radius);
            int x = 0;
            for (; x < left; ++x) silhouetteAt(job, x, y);
            if (!job.disk.empty() && right > left) x = silhouetteSpan(job, y, left, right);
            for (; x < w; ++x) silhouetteAt(job, x, y);
        }
    });
}

}  // namespace darkroom::passes
