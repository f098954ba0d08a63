// Depth and normal pyramids (depth_pyramid.h). Each level is built row by row
// from the one below; every texel depends on its sources only, so the result
// is the same for any thread count.
#include "depth_pyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::ssao {
namespace {

constexpr float kInf = std::numeric_limits<float>::infinity();

void allocate(PyramidLevel& l, int w, int h, bool withSource) {
    l.width = w, l.height = h;
    const std::size_t size = std::size_t(w) * std::size_t(h);
    l.z.assign(size, kInf);
    for (auto& c : l.n) c.assign(size, 0.0f);
    if (withSource) l.source.assign(size, 0);
}

// McGuire et al.'s rotated grid: alternating sources keep every level an
// unbiased, well-spread sample of real depths.
void subsampleRow(const PyramidLevel& src, PyramidLevel& dst, int y) {
    for (int x = 0; x < dst.width; ++x) {
        const int sx = std::min(2 * x + ((y & 1) ^ 1), src.width - 1);
        const int sy = std::min(2 * y + ((x & 1) ^ 1), src.height - 1);
        const std::size_t i = src.at(sx, sy), o = dst.at(x, y);
        dst.z[o] = src.z[i];
        for (int c = 0; c < 3; ++c) dst.n[c][o] = src.n[c][i];
        dst.source[o] = src.source[i];
    }
}

void meanRow(const PyramidLevel& src, PyramidLevel& dst, int y) {
    for (int x = 0; x < dst.width; ++x) {
        float z = 0, n[3] = {0, 0, 0};
        int count = 0;
        for (int dy = 0; dy < 2; ++dy)
            for (int dx = 0; dx < 2; ++dx) {
                const int sx = 2 * x + dx, sy = 2 * y + dy;
                if (sx >= src.width || sy >= src.height) continue;
                const std::size_t i = src.at(sx, sy);
                if (!(src.z[i] < kInf)) continue;
                z += src.z[i];
                for (int c = 0; c < 3; ++c) n[c] += src.n[c][i];
                ++count;
            }
        if (count == 0) continue;  // stays background
        const std::size_t o = dst.at(x, y);
        dst.z[o] = z / float(count);
        const float len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int c = 0; c < 3; ++c) dst.n[c][o] = len > 0 ? n[c] / len : 0.0f;
    }
}

}  // namespace

Pyramid buildPyramid(const Frame& g, Reduction reduction, int maxLevel, Context& ctx) {
    Pyramid p;
    p.levels.emplace_back();
    PyramidLevel& base = p.levels.back();
    const bool withSource = reduction == Reduction::RotatedGrid;
    allocate(base, g.width(), g.height(), withSource);
    ctx.parallelFor(0, g.height(), 32, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            const std::size_t row = g.offset(0, y);
            std::copy_n(g.z + row, g.width(), base.z.begin() + std::ptrdiff_t(base.at(0, y)));
            for (int c = 0; c < 3; ++c) std::copy_n(g.n[c] + row, g.width(), base.n[c].begin() + std::ptrdiff_t(base.at(0, y)));
            if (withSource)
                for (int x = 0; x < g.width(); ++x) base.source[base.at(x, y)] = std::uint32_t(base.at(x, y));
        }
    });
    while (int(p.levels.size()) <= maxLevel) {
        const PyramidLevel& src = p.levels.back();
        if (src.width <= 1 && src.height <= 1) break;
        PyramidLevel next;
        allocate(next, (src.width + 1) / 2, (src.height + 1) / 2, withSource);
        ctx.parallelFor(0, next.height, 16, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y) reduction == Reduction::RotatedGrid ? subsampleRow(src, next, y) : meanRow(src, next, y);
        });
        p.levels.push_back(std::move(next));
    }
    return p;
}

}  // namespace darkroom::ssao
