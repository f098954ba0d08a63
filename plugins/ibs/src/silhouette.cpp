#include "silhouette.h"

#include <cmath>
#include <utility>

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

std::vector<float> silhouette(Context& ctx, const float* depth, const std::uint32_t* ids, int w, int h,
                              const SilhouetteOptions& o) {
    std::vector<float> out(std::size_t(w) * std::size_t(h), 0.0f);
    // Disk of offsets, nearest first so most edge pixels stop early.
    std::vector<std::pair<int, int>> disk;
    const int r = int(std::floor(o.width + 1e-9));
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
            if ((dx || dy) && dx * dx + dy * dy <= o.width * o.width + 1e-9) disk.emplace_back(dx, dy);
    std::stable_sort(disk.begin(), disk.end(), [](const auto& a, const auto& b) {
        return a.first * a.first + a.second * a.second < b.first * b.first + b.second * b.second;
    });
    if (disk.empty()) return out;
    ctx.parallelFor(0, h, 4, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * w + x;
                const float zp = depth[i];
                if (!hasData(zp)) continue;
                const std::uint32_t ip = ids ? ids[i] : 0;
                for (const auto& [dx, dy] : disk) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const std::size_t j = std::size_t(qy) * w + qx;
                    const float zq = depth[j];
                    if (!hasData(zq)) continue;
                    const std::uint32_t iq = ids ? ids[j] : 0;
                    const bool edge = o.nearSide ? nearOfEdge(zp, zq, ip, iq, ids != nullptr, o.depthThreshold)
                                                 : nearOfEdge(zq, zp, iq, ip, ids != nullptr, o.depthThreshold);
                    if (edge) {
                        out[i] = 1.0f;
                        break;
                    }
                }
            }
    });
    return out;
}

}  // namespace darkroom::passes
