#include "primitive_grid.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace darkroom::listao {

namespace {

constexpr double kMaxCells = 2.0e6;

// Sorts the indices [0, cells.size()) by cell (stable counting sort) and
// returns the per-cell start offsets, one past the end last.
std::vector<std::uint32_t> countingOrder(const std::vector<std::size_t>& cells, std::size_t cellCount,
                                         std::vector<std::uint32_t>& order) {
    std::vector<std::uint32_t> start(cellCount + 1, 0);
    for (std::size_t c : cells) ++start[c + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
    order.assign(cells.size(), 0);
    for (std::size_t i = 0; i < cells.size(); ++i) order[next[cells[i]]++] = std::uint32_t(i);
    return start;
}

template <class T>
std::vector<T> permuted(const std::vector<T>& v, const std::vector<std::uint32_t>& order) {
    std::vector<T> out(v.size());
    for (std::size_t i = 0; i < order.size(); ++i) out[i] = v[order[i]];
    return out;
}

V3f middle(V3f a, V3f b) { return (a + b) * 0.5f; }

}  // namespace

PrimitiveGrid::PrimitiveGrid(Primitives p, float cell) : p_(std::move(p)) {
    if (p_.centres.size() + p_.segA.size() > std::numeric_limits<std::uint32_t>::max() / 2)
        throw Error("point list too large for ambient occlusion (over two billion primitives)");
    float lo[3] = {std::numeric_limits<float>::max(), std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
    float hi[3] = {-lo[0], -lo[1], -lo[2]};
    auto grow = [&](V3f a) {
        const float c[3] = {a.x, a.y, a.z};
        for (int k = 0; k < 3; ++k) lo[k] = std::min(lo[k], c[k]), hi[k] = std::max(hi[k], c[k]);
    };
    for (std::size_t i = 0; i < p_.centres.size(); ++i) {
        grow(p_.centres[i]);
        sphereReach_ = std::max(sphereReach_, p_.radii[i]);
    }
    for (std::size_t i = 0; i < p_.segA.size(); ++i) {
        grow(middle(p_.segA[i], p_.segB[i]));
        segmentReach_ = std::max(segmentReach_, 0.5f * length(p_.segB[i] - p_.segA[i]) +
                                                    std::max(p_.segRa[i], p_.segRb[i]));
    }
    if (p_.centres.empty() && p_.segA.empty()) return;
    origin_ = {lo[0], lo[1], lo[2]};
    // Cells of the wanted width unless the bounds would need too many.
    const double volume = double(std::max(hi[0] - lo[0], cell)) * std::max(hi[1] - lo[1], cell) *
                          std::max(hi[2] - lo[2], cell);
    cell_ = float(std::max(double(cell), std::cbrt(volume / kMaxCells)));
    if (!(cell_ > 0) || !std::isfinite(cell_)) cell_ = 1;
    for (int k = 0; k < 3; ++k) dims_[k] = std::max(1, int(std::floor((hi[k] - lo[k]) / cell_)) + 1);
    const std::size_t cells = std::size_t(dims_[0]) * std::size_t(dims_[1]) * std::size_t(dims_[2]);

    std::vector<std::uint32_t> order;
    std::vector<std::size_t> at(p_.centres.size());
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = cellOf(p_.centres[i]);
    sphereStart_ = countingOrder(at, cells, order);
    p_.centres = permuted(p_.centres, order);
    p_.radii = permuted(p_.radii, order);
    at.resize(p_.segA.size());
    for (std::size_t i = 0; i < at.size(); ++i) at[i] = cellOf(middle(p_.segA[i], p_.segB[i]));
    segmentStart_ = countingOrder(at, cells, order);
    p_.segA = permuted(p_.segA, order);
    p_.segB = permuted(p_.segB, order);
    p_.segRa = permuted(p_.segRa, order);
    p_.segRb = permuted(p_.segRb, order);
    for (std::size_t i = 0; i < p_.segA.size(); ++i) {
        const V3f ab = p_.segB[i] - p_.segA[i];
        const float len = length(ab);
        p_.segMid.push_back(middle(p_.segA[i], p_.segB[i]));
        p_.segDir.push_back(len > 0 ? ab * (1.0f / len) : V3f{0, 0, 0});
        p_.segLen.push_back(len);
        p_.segReach.push_back(0.5f * len + std::max(p_.segRa[i], p_.segRb[i]));
    }
    if (p_.centres.empty()) sphereStart_.clear();
    if (p_.segA.empty()) segmentStart_.clear();
}

std::size_t PrimitiveGrid::cellOf(V3f a) const {
    const float c[3] = {a.x, a.y, a.z}, o[3] = {origin_.x, origin_.y, origin_.z};
    std::size_t idx[3];
    for (int k = 0; k < 3; ++k) idx[k] = std::size_t(std::clamp(int((c[k] - o[k]) / cell_), 0, dims_[k] - 1));
    return (idx[2] * std::size_t(dims_[1]) + idx[1]) * std::size_t(dims_[0]) + idx[0];
}

}  // namespace darkroom::listao
