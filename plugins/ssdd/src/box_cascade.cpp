#include "box_cascade.h"

#include <algorithm>
#include <cmath>

namespace darkroom::passes {

BoxCascade boxCascade(double sigma, int imageSize) {
    sigma = std::min(sigma, double(std::max(imageSize, 1)));
    const double v = sigma * sigma / kBoxes;  // variance of each box
    ExtendedBox b;
    // The widest plain box with variance r (r + 1) / 3 <= v ...
    b.radius = int(std::floor(0.5 * (std::sqrt(1.0 + 12.0 * v) - 1.0)));
    while (double(b.radius + 1) * (b.radius + 2) / 3.0 <= v) ++b.radius;  // rounding of the root
    while (b.radius > 0 && double(b.radius) * (b.radius + 1) / 3.0 > v) --b.radius;
    // ... and the end weight that brings it to v exactly.
    const double r = b.radius;
    b.alpha = (2 * r + 1) * (r * (r + 1) / 3.0 - v) / (2.0 * (v - (r + 1) * (r + 1)));
    b.alpha = std::clamp(b.alpha, 0.0, 1.0);
    BoxCascade c;
    c.fill(b);
    return c;
}

int cascadeMargin(const BoxCascade& c, int k) {
    int m = 0;
    for (int j = k + 1; j < kBoxes; ++j) m += c[std::size_t(j)].radius + 1;
    return m;
}

std::vector<double> cascadeWeights(const BoxCascade& c) {
    std::vector<double> k{1.0};
    for (const ExtendedBox& b : c) {
        std::vector<double> box(std::size_t(2 * b.radius + 3), 1.0);
        box.front() = box.back() = b.alpha;
        std::vector<double> next(k.size() + box.size() - 1, 0.0);
        for (std::size_t i = 0; i < k.size(); ++i)
            for (std::size_t j = 0; j < box.size(); ++j) next[i + j] += k[i] * box[j];
        k = std::move(next);
    }
    return k;
}

}  // namespace darkroom::passes
