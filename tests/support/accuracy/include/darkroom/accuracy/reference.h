#pragma once
// Ray-traced references for the accuracy harness (issue 6): what an image-space
// pass approximates, computed by tracing rays through a CaptureBackend
// (render() for the primary hits, trace() and occluded() for the rest) with the
// same camera as the pass's input. Deterministic: random numbers are hashes of
// (pixel, sample, seed), so any thread count gives the same image.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/capture_backend.h>
#include <darkroom/colormap.h>
#include <darkroom/export.h>

#include <cstdint>
#include <functional>
#include <string>

namespace darkroom {
class Context;
}

namespace darkroom::reference {

// How AO weights the directions of the hemisphere around the normal N:
//  Cosine:  AO = (1/pi) Int V(w) (w.N) dw   (what SSAO's horizon method estimates)
//  Uniform: AO = (1/2pi) Int V(w) dw
// V(w) = 1 when the ray from the surface point along w hits nothing within the
// radius. AO = 1 means unoccluded.
enum class AoWeighting { Cosine, Uniform };

DARKROOM_API const char* toString(AoWeighting w);

struct AoOptions {
    AoWeighting weighting = AoWeighting::Cosine;
    // Occlusion radius: world units, or (radiusInImageHeights) a fraction of
    // the image height converted at each pixel's depth exactly as SSAO's
    // `radiusUnits: imageHeight` does (radius * height * pixelSizeAt(Z)).
    double radius = 0.05;
    bool radiusInImageHeights = false;
    int samples = 64;  // rays per pixel, >= 1
    std::uint32_t seed = 0;
};

// Ray-traced AO of the camera's view. Returns a buffer of the camera's size
// with "Z" (planar depth, +inf on background), "AO" (the mean visibility of
// `samples` independent rays, 1 on background) and "AO.stderr" (the standard
// error of that mean, s / sqrt(N) with s the sample standard deviation; 0 on
// background, NaN when samples = 1), and the camera in its metadata. A hit
// without a usable normal gets NaN in both. Rays leave the hit point
// lifted by a small offset along the geometric normal, which faces the camera.
// Throws darkroom::Error on bad options.
DARKROOM_API BufferPtr ambientOcclusion(CaptureBackend& backend, const Camera& camera,
                                        const AoOptions& options, Context& ctx);

// Turns G-buffer sample `index` of `samples` (as returned by
// CaptureBackend::trace for a request) into a colour. The references average
// what it returns componentwise, so it should return premultiplied RGBA (or
// an opaque colour composited over a background, which is the same thing).
using SampleShader = std::function<void(const Buffer& samples, std::size_t index, float rgba[4])>;

// The shading of a ColorMapping node with `colorMap` over [lo, hi] on scalar
// `field`, composited over an opaque `background`: a hit gets the map's linear
// colour at (value - lo) / (hi - lo) (NaN value: the map's NaN colour), a
// miss gets `background`. Alpha is 1. The request it needs: Z and `field`.
DARKROOM_API SampleShader colorMapShader(std::string field, ColorMapData colorMap, double lo, double hi,
                                         Color background);

// n x n samples per pixel on a regular grid of sub-pixel centres
// (x + (i + 0.5) / n, y + (j + 0.5) / n), each traced with `request`, shaded,
// then averaged with equal weights: the anti-aliasing reference (16 x 16 in
// the harness). Returns "R", "G", "B", "A" of the camera's size, camera in the
// metadata. Works in bounded memory (a few million samples at a time).
DARKROOM_API BufferPtr supersampled(CaptureBackend& backend, const Camera& camera,
                                    const CaptureRequest& request, const SampleShader& shade, int n,
                                    Context& ctx);

// A thin lens in the camera plane (perpendicular to the view direction, at the
// camera position) with diameter `aperture`, focused at planar depth
// `focalDistance` (world units): the model of the SSDoF pass, whose circle of
// confusion on the focal plane has diameter aperture * |z - z_f| / z.
struct ThinLens {
    double aperture = 0.05;
    double focalDistance = 1.0;
    int lensSamples = 256;  // points on the lens per pixel
    // Each lens sample also gets a sub-pixel position; pixelJitter = false puts
    // all of them at the pixel centre (pure defocus, no anti-aliasing).
    bool pixelJitter = true;
    std::uint32_t seed = 0;
};

// Thin-lens depth of field: for each pixel, `lensSamples` rays from points
// spread evenly over the lens disc through the pixel's point on the focal
// plane, traced, shaded and averaged. A perspective camera is required (an
// orthographic one throws darkroom::Error). Returns "R", "G", "B", "A" like
// supersampled(); with aperture 0 it equals supersampled() at n = 1 when
// pixelJitter is off.
DARKROOM_API BufferPtr thinLens(CaptureBackend& backend, const Camera& camera, const CaptureRequest& request,
                                const SampleShader& shade, const ThinLens& lens, Context& ctx);

// Transparency (issue 30): for each pixel-centre ray, every surface crossing
// in exact depth order (traced again from just beyond each hit), each shaded
// by `shadeCrossing` into a straight colour and its opacity (rgba[3]), then
// composited front to back over the opaque `background`:
//   C = sum_k a_k c_k prod_{j<k} (1 - a_j) + prod_k (1 - a_k) background.
// At most `maxCrossings` per ray; a ray stops early once what is behind can
// no longer show (transmittance below 1e-5). Returns "R", "G", "B", "A" (1)
// and "crossings" (how many surfaces each ray crossed: the depth complexity
// up to the stop) with the camera in the metadata.
DARKROOM_API BufferPtr transparent(CaptureBackend& backend, const Camera& camera, const CaptureRequest& request,
                                   const SampleShader& shadeCrossing, Color background, int maxCrossings,
                                   Context& ctx);

}  // namespace darkroom::reference
