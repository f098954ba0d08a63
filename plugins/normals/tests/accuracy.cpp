#include "accuracy.h"

#include <darkroom/math.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace darkroom::test {

namespace {

AngleStats summarise(std::vector<double> a) {
    AngleStats s;
    s.count = a.size();
    if (a.empty()) return s;
    std::sort(a.begin(), a.end());
    double sum = 0;
    for (double v : a) sum += v;
    s.mean = sum / double(a.size());
    s.median = a[a.size() / 2];
    s.p95 = a[std::min(a.size() - 1, std::size_t(0.95 * double(a.size())))];
    return s;
}

Vec3 normalAt(const Buffer& b, std::size_t i) {
    return {b.hostFloat("N.x")[i], b.hostFloat("N.y")[i], b.hostFloat("N.z")[i]};
}

}  // namespace

NormalAccuracy compareNormals(const Buffer& truth, const Buffer& rec, double jump) {
    const int w = truth.width(), h = truth.height();
    const float* z = truth.requireFloat("Z");
    std::vector<double> edges, interior;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * w + x;
            if (!std::isfinite(z[i])) continue;
            bool edge = false;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const float zq = z[std::size_t(qy) * w + qx];
                    if (!std::isfinite(zq) || std::abs(zq - z[i]) > jump * z[i]) edge = true;
                }
            const Vec3 a = normalAt(truth, i), b = normalAt(rec, i);
            const double c = std::clamp(dot(normalize(a), normalize(b)), -1.0, 1.0);
            (edge ? edges : interior).push_back(std::acos(c) * 180.0 / std::numbers::pi);
        }
    return {summarise(edges), summarise(interior)};
}

}  // namespace darkroom::test
