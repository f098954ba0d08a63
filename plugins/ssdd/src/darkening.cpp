#include "darkening.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace darkroom::passes {

std::size_t rowScratch(const DarkeningJob& job) {
    // Four blocks with the cascade's margins, and a row without surface for
    // the rows past the bottom.
    const std::size_t samples = std::size_t(job.width) + 2 * std::size_t(cascadeMargin(job.horizontal, 0));
    return 4 * samples * kBlockRows + std::size_t(job.width);
}
std::size_t columnScratch(const DarkeningJob& job) {
    // Four strips with margins, the strip's depth, its mask sums in double.
    const std::size_t samples = std::size_t(job.height) + 2 * std::size_t(cascadeMargin(job.vertical, 0));
    return (4 * samples + std::size_t(job.height)) * kStripColumns + 2 * std::size_t(job.height) * kStripColumns;
}

namespace {

// Scratch memory of the calling thread, kept between runs (its pages stay
// mapped, like the host's plane pool).
float* threadScratch(std::size_t floats) {
    thread_local std::vector<float> scratch;
    if (scratch.size() < floats) scratch.resize(floats);
    return scratch.data();
}

}  // namespace

void depthDarkening(Context& ctx, const DarkeningJob& job) {
    const int w = job.width, h = job.height;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    // The minimum is the same whatever the order chunks are merged in.
    float reference = std::numeric_limits<float>::infinity();
    std::mutex mutex;
    ctx.parallelFor(0, h, 64, [&](int y0, int y1) {
        const float r = nearestDepth(job.depth, std::size_t(y0) * w, std::size_t(y1) * w);
        std::lock_guard<std::mutex> lock(mutex);
        reference = std::min(reference, r);
    });
    if (!std::isfinite(reference)) {  // no surface at all
        std::fill_n(job.factor, n, 1.0f);
        return;
    }
    // The sums along rows, in planes from the host's pool (no page faults
    // when the pass runs again).
    const auto sums = ctx.allocate(w, h, {"depth", "mask"}, Fill::None);
    const BlurPlanes planes{sums->writeFloat("depth"), sums->writeFloat("mask")};
    const int blocks = (h + kBlockRows - 1) / kBlockRows;
    ctx.parallelFor(0, blocks, 1, [&](int b0, int b1) {
        float* scratch = threadScratch(rowScratch(job));
        for (int b = b0; b < b1; ++b) blurRows(job, reference, b * kBlockRows, planes, scratch);
    });
    if (ctx.cancelled()) throw Cancelled();
    const int strips = (w + kStripColumns - 1) / kStripColumns;
    ctx.parallelFor(0, strips, 1, [&](int s0, int s1) {
        float* scratch = threadScratch(columnScratch(job));
        for (int s = s0; s < s1; ++s) blurColumnsAndDarken(job, reference, s * kStripColumns, planes, scratch);
    });
    if (ctx.cancelled()) throw Cancelled();
}

}  // namespace darkroom::passes
