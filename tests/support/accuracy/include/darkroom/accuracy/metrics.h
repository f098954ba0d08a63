#pragma once
// Image-comparison metrics for the accuracy harness (DESIGN.md §9): RMSE, PSNR,
// signed bias, SSIM (Wang et al. 2004) and angular error between normal fields,
// each over an optional pixel mask, plus the edge/interior masks that split every
// statistic into pixels near a depth or id discontinuity and the rest.
//
// Images are planar arrays (one float per pixel, rows top to bottom), as stored
// by darkroom::Buffer. A mask is one byte per pixel, non-zero = use the pixel;
// a null mask uses every pixel. NaN in either image is "no data": the pixel is
// skipped and counted in `skipped`, never folded into a statistic. Statistics
// over zero pixels are NaN with count 0.
#include <darkroom/buffer.h>
#include <darkroom/export.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom::metrics {

// One scalar statistic and the pixels it was computed from.
struct Measure {
    double value = 0.0;         // NaN when count == 0
    std::size_t count = 0;      // pixels (or SSIM windows) used
    std::size_t skipped = 0;    // selected by the mask but skipped for NaN
};

// sqrt(mean((a - b)^2)).
DARKROOM_API Measure rmse(const float* a, const float* b, std::size_t n,
                          const std::uint8_t* mask = nullptr);
// 20 log10(peak / rmse); +infinity for identical images.
DARKROOM_API Measure psnr(const float* a, const float* b, std::size_t n, double peak = 1.0,
                          const std::uint8_t* mask = nullptr);
// mean(a - b): positive when a is brighter than b.
DARKROOM_API Measure bias(const float* a, const float* b, std::size_t n,
                          const std::uint8_t* mask = nullptr);

// The same on one float channel of two buffers of equal size (throws
// darkroom::Error on a size mismatch or a missing channel).
DARKROOM_API Measure rmse(const Buffer& a, const Buffer& b, std::string_view channel,
                          const std::uint8_t* mask = nullptr);
DARKROOM_API Measure psnr(const Buffer& a, const Buffer& b, std::string_view channel,
                          double peak = 1.0, const std::uint8_t* mask = nullptr);
DARKROOM_API Measure bias(const Buffer& a, const Buffer& b, std::string_view channel,
                          const std::uint8_t* mask = nullptr);

// --- SSIM -------------------------------------------------------------------
// Wang, Bovik, Sheikh, Simoncelli 2004, exactly as their reference ssim_index.m:
// an 11x11 Gaussian window with sigma 1.5 normalised to sum 1, K1 = 0.01,
// K2 = 0.03, C1 = (K1 L)^2, C2 = (K2 L)^2 with L the dynamic range, and
//   SSIM = (2 mu_a mu_b + C1)(2 sigma_ab + C2) / ((mu_a^2 + mu_b^2 + C1)(sigma_a^2 + sigma_b^2 + C2))
// with the biased (window-weighted) variances. Borders: only window positions
// lying fully inside the image are used ('valid' filtering), so the map is
// (width-10) x (height-10) and its entry (i, j) belongs to the window centred on
// pixel (i+5, j+5). No downsampling. Computed in double precision.
// A window containing NaN is skipped (counted in `skipped`); with a mask, a
// window is used when the mask is set at its centre pixel. Images smaller than
// 11x11 give count 0.
inline constexpr int kSsimWindow = 11;
inline constexpr double kSsimSigma = 1.5;
inline constexpr double kSsimK1 = 0.01;
inline constexpr double kSsimK2 = 0.03;

// The SSIM map over valid window positions, row-major (width-10) x (height-10);
// NaN where a window holds NaN. Empty for images smaller than the window.
DARKROOM_API std::vector<double> ssimMap(const float* a, const float* b, int width, int height,
                                         double dynamicRange = 1.0);
// Mean SSIM (MSSIM) over the valid windows selected by the mask.
DARKROOM_API Measure ssim(const float* a, const float* b, int width, int height,
                          double dynamicRange = 1.0, const std::uint8_t* mask = nullptr);
DARKROOM_API Measure ssim(const Buffer& a, const Buffer& b, std::string_view channel,
                          double dynamicRange = 1.0, const std::uint8_t* mask = nullptr);

// --- Angular error between normal fields -----------------------------------
// Both fields are three planar components (not necessarily unit length). A pixel
// is skipped (counted) when any component of either field is NaN or infinite, or
// either vector has zero length (background). The angle is atan2(|a x b|, a . b)
// in degrees, accurate near 0 and 180. Percentiles interpolate linearly between
// order statistics (numpy's default): p at rank p/100 * (count - 1).
struct AngularStats {
    double mean = 0.0, median = 0.0, p95 = 0.0;
    double shareAbove5 = 0.0;   // fraction of used pixels with error > 5 degrees
    std::size_t count = 0, skipped = 0;
};

using NormalField = std::array<const float*, 3>;

DARKROOM_API AngularStats angularError(const NormalField& a, const NormalField& b, std::size_t n,
                                       const std::uint8_t* mask = nullptr);
// On buffers; the channels default to the captured world normals.
DARKROOM_API AngularStats angularError(const Buffer& a, const Buffer& b,
                                       const std::array<std::string, 3>& channels = {"N.x", "N.y", "N.z"},
                                       const std::uint8_t* mask = nullptr);

// --- Edge and interior masks -----------------------------------------------
// Two 8-neighbours p, q are separated by a discontinuity when
//  - exactly one of them is background (depth not finite: +inf or NaN), or
//  - both have finite depth and |z_p - z_q| > relativeJump * min(z_p, z_q), or
//  - their object ids differ.
// `edge` marks every pixel with such a separated 8-neighbour, i.e. the pixels on
// both sides within 1 px of the discontinuity (a vertical step between columns
// k-1 and k marks exactly those two columns). `interior` marks valid pixels
// (finite depth; every pixel when no depth is given) that are not edge pixels.
// Background pixels next to an object are edge pixels; background elsewhere is
// in neither mask. depth or ids may be null (that criterion is then unused).
struct EdgeMasks {
    int width = 0, height = 0;
    std::vector<std::uint8_t> edge, interior;
};

inline constexpr double kDefaultRelativeJump = 0.05;

DARKROOM_API EdgeMasks edgeMasks(const float* depth, const std::uint32_t* ids, int width, int height,
                                 double relativeJump = kDefaultRelativeJump);
// From a G-buffer: depth channel `depthChannel` and, when present, the uint32
// channel `idChannel` (pass an empty name to ignore ids).
DARKROOM_API EdgeMasks edgeMasks(const Buffer& gbuffer, std::string_view depthChannel = "Z",
                                 std::string_view idChannel = "objectId",
                                 double relativeJump = kDefaultRelativeJump);

// A statistic over all pixels, edge pixels and interior pixels.
template <class T>
struct MetricsSplit {
    T all, edge, interior;
};

// Calls f(mask) with a null mask, the edge mask and the interior mask:
//   auto e = split(masks, [&](const std::uint8_t* m) { return rmse(a, b, n, m); });
template <class F>
auto split(const EdgeMasks& masks, F&& f) -> MetricsSplit<decltype(f(static_cast<const std::uint8_t*>(nullptr)))> {
    return {f(static_cast<const std::uint8_t*>(nullptr)), f(masks.edge.data()), f(masks.interior.data())};
}

}  // namespace darkroom::metrics
