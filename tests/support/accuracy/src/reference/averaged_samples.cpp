// References that average shaded ray samples per pixel: n x n supersampling
// and the thin lens. Both generate rays a band of rows at a time, trace them
// with the backend, shade each sample and average.
#include "sampling.h"

#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/reference.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace darkroom::reference {

namespace {

constexpr std::size_t kRaysPerBatch = std::size_t(1) << 21;

// Writes ray k of pixel (x, y) into batch slot r.
using RayFn = std::function<void(int x, int y, std::size_t k, Vec3& origin, Vec3& direction)>;

BufferPtr averageSamples(CaptureBackend& backend, const Camera& camera, const CaptureRequest& request,
                         const SampleShader& shade, std::size_t perPixel, const RayFn& makeRay,
                         const std::string& what, Context& ctx) {
    if (camera.width <= 0 || camera.height <= 0)
        throw Error(what + ": the camera's resolution must be positive");
    if (!shade) throw Error(what + ": no shader given");
    const int w = camera.width, h = camera.height;
    auto out = ctx.allocate(w, h, {{"R"}, {"G"}, {"B"}, {"A"}});
    out->metadata().camera = camera;
    float* dst[4] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B"), out->writeFloat("A")};
    const int rowsPerBatch = int(std::max<std::size_t>(1, kRaysPerBatch / (perPixel * std::size_t(w))));
    RayBatch rays;
    for (int y0 = 0; y0 < h; y0 += rowsPerBatch) {
        const int y1 = std::min(h, y0 + rowsPerBatch);
        const std::size_t total = std::size_t(y1 - y0) * std::size_t(w) * perPixel;
        rays.origins.resize(3 * total);
        rays.directions.resize(3 * total);
        ctx.parallelFor(y0, y1, 1, [&](int ya, int yb) {
            for (int y = ya; y < yb; ++y)
                for (int x = 0; x < w; ++x)
                    for (std::size_t k = 0; k < perPixel; ++k) {
                        const std::size_t r = (std::size_t(y - y0) * w + x) * perPixel + k;
                        Vec3 o, d;
                        makeRay(x, y, k, o, d);
                        rays.origins[3 * r] = float(o.x), rays.origins[3 * r + 1] = float(o.y),
                        rays.origins[3 * r + 2] = float(o.z);
                        rays.directions[3 * r] = float(d.x), rays.directions[3 * r + 1] = float(d.y),
                        rays.directions[3 * r + 2] = float(d.z);
                    }
        });
        const BufferPtr samples = backend.trace(rays, request, ctx);
        if (ctx.cancelled()) throw Cancelled();
        ctx.parallelFor(y0, y1, 1, [&](int ya, int yb) {
            for (int y = ya; y < yb; ++y)
                for (int x = 0; x < w; ++x) {
                    double sum[4] = {0, 0, 0, 0};
                    const std::size_t first = (std::size_t(y - y0) * w + x) * perPixel;
                    for (std::size_t k = 0; k < perPixel; ++k) {
                        float c[4] = {0, 0, 0, 0};
                        shade(*samples, first + k, c);
                        for (int j = 0; j < 4; ++j) sum[j] += c[j];
                    }
                    const std::size_t i = std::size_t(y) * w + x;
                    for (int j = 0; j < 4; ++j) dst[j][i] = float(sum[j] / double(perPixel));
                }
        });
        ctx.progress(double(y1) / h);
    }
    return out;
}

}  // namespace

BufferPtr supersampled(CaptureBackend& backend, const Camera& camera, const CaptureRequest& request,
                       const SampleShader& shade, int n, Context& ctx) {
    if (n < 1 || n > 64)
        throw Error("reference supersampling: n is " + std::to_string(n) + "; expected 1 to 64 (n x n samples)");
    const std::size_t perPixel = std::size_t(n) * std::size_t(n);
    const double step = 1.0 / n;
    return averageSamples(
        backend, camera, request, shade, perPixel,
        [&](int x, int y, std::size_t k, Vec3& o, Vec3& d) {
            camera.ray(x + (double(k % std::size_t(n)) + 0.5) * step, y + (double(k / std::size_t(n)) + 0.5) * step,
                       o, d);
        },
        "reference supersampling", ctx);
}

BufferPtr thinLens(CaptureBackend& backend, const Camera& camera, const CaptureRequest& request,
                   const SampleShader& shade, const ThinLens& lens, Context& ctx) {
    if (camera.projection != Camera::Projection::Perspective)
        throw Error("reference thin lens: the camera is orthographic; a thin lens needs a perspective camera");
    if (!(lens.aperture >= 0.0) || !std::isfinite(lens.aperture))
        throw Error("reference thin lens: the aperture must be finite and >= 0");
    if (!(lens.focalDistance > 0.0) || !std::isfinite(lens.focalDistance))
        throw Error("reference thin lens: the focal distance must be positive and finite");
    if (lens.lensSamples < 1)
        throw Error("reference thin lens: lensSamples is " + std::to_string(lens.lensSamples) +
                    "; expected at least 1");
    Vec3 right, up, fwd;
    camera.basis(right, up, fwd);
    const std::size_t perPixel = std::size_t(lens.lensSamples);
    const double radius = 0.5 * lens.aperture, zf = lens.focalDistance;
    // Golden-angle spiral: lens points spread evenly over the disc (equal
    // area per point); each pixel turns the spiral by its own angle so the
    // pattern's structure does not repeat from pixel to pixel.
    const double golden = detail::kPi * (3.0 - std::sqrt(5.0));
    return averageSamples(
        backend, camera, request, shade, perPixel,
        [&](int x, int y, std::size_t k, Vec3& o, Vec3& d) {
            const std::uint64_t pixel = std::uint64_t(y) * std::uint64_t(camera.width) + std::uint64_t(x);
            const double spin = 2.0 * detail::kPi * detail::uniform(pixel, 0, lens.seed, 7);
            const double rr = radius * std::sqrt((double(k) + 0.5) / double(perPixel));
            const double a = spin + golden * double(k);
            double px = x + 0.5, py = y + 0.5;
            if (lens.pixelJitter) {
                px = x + detail::uniform(pixel, std::uint32_t(k), lens.seed, 0);
                py = y + detail::uniform(pixel, std::uint32_t(k), lens.seed, 1);
            }
            // The pixel's point on the focal plane, seen through the lens
            // point: every lens ray meets there, so the focal plane is sharp.
            const Vec3 focus = camera.worldPosition(px, py, zf);
            o = camera.position + right * (rr * std::cos(a)) + up * (rr * std::sin(a));
            // Forward component 1: t is the planar depth of the hit.
            d = (focus - o) * (1.0 / zf);
        },
        "reference thin lens", ctx);
}

}  // namespace darkroom::reference
