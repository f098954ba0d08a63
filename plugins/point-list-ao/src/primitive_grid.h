#pragma once
// The spheres and round line segments of a point list in the camera's view
// space (relative to the eye, so float precision holds far from the world
// origin), sorted into a uniform grid of cells about half the AO radius wide:
// a receiver visits only the cells within its reach, and each row of cells
// along x is one contiguous run of primitives.
#include <darkroom/view_geometry.h>

#include <cstdint>
#include <vector>

namespace darkroom::listao {

struct Primitives {
    std::vector<V3f> centres;  // spheres
    std::vector<float> radii;
    std::vector<V3f> segA, segB;  // round line segments, radius ra at a to rb at b
    std::vector<float> segRa, segRb;
    // Derived by PrimitiveGrid, per segment: its middle, unit direction,
    // length and the largest distance from the middle to its surface.
    std::vector<V3f> segMid, segDir;
    std::vector<float> segLen, segReach;
};

class PrimitiveGrid {
public:
    // `cell`: the wanted cell width; made larger when the list's bounds
    // would need more than about two million cells.
    PrimitiveGrid(Primitives primitives, float cell);

    const Primitives& primitives() const { return p_; }

    // Calls spheres(begin, end) and segments(begin, end) for every run of
    // indices (into primitives()) whose cell may hold a primitive within
    // `range` of q: the anchor's cell (sphere centre, segment middle) lies
    // within range plus the largest primitive's reach of q.
    template <class SphereFn, class SegmentFn>
    void visit(V3f q, float range, SphereFn&& spheres, SegmentFn&& segments) const {
        visitKind(q, range + sphereReach_, sphereStart_, spheres);
        visitKind(q, range + segmentReach_, segmentStart_, segments);
    }

private:
    template <class Fn>
    void visitKind(V3f q, float reach, const std::vector<std::uint32_t>& start, Fn&& fn) const {
        if (start.empty()) return;
        int lo[3], hi[3];
        const float c[3] = {q.x, q.y, q.z}, o[3] = {origin_.x, origin_.y, origin_.z};
        for (int k = 0; k < 3; ++k) {
            const float a = (c[k] - reach - o[k]) / cell_, b = (c[k] + reach - o[k]) / cell_;
            if (b < 0 || a >= float(dims_[k])) return;
            lo[k] = a < 0 ? 0 : int(a);
            hi[k] = b >= float(dims_[k]) ? dims_[k] - 1 : int(b);
        }
        for (int z = lo[2]; z <= hi[2]; ++z)
            for (int y = lo[1]; y <= hi[1]; ++y) {
                const std::size_t row = (std::size_t(z) * std::size_t(dims_[1]) + std::size_t(y)) * std::size_t(dims_[0]);
                const std::uint32_t b = start[row + std::size_t(lo[0])], e = start[row + std::size_t(hi[0]) + 1];
                if (b < e) fn(b, e);
            }
    }
    std::size_t cellOf(V3f anchor) const;

    Primitives p_;
    V3f origin_{0, 0, 0};
    float cell_ = 1;
    int dims_[3] = {1, 1, 1};
    float sphereReach_ = 0, segmentReach_ = 0;  // the largest distance from an anchor to its primitive's surface
    std::vector<std::uint32_t> sphereStart_, segmentStart_;  // per cell, then one past the last
};

}  // namespace darkroom::listao
