// The transparency reference (issue 30): every surface crossing along each
// pixel-centre ray, in exact depth order, shaded and composited front to back
// over an opaque background — what a capture with unbounded layers followed by
// ColorMapping with the same opacities would give. Rays are traced again from
// just beyond each hit until they miss, run out of `maxCrossings`, or what is
// behind can no longer show (transmittance below 1e-5).
#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/reference.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace darkroom::reference {

namespace {

// A crossing this close behind the last (relative to its depth) is the same
// surface hit again (a shared edge), not a new one.
constexpr double kSameSurface = 1e-5;
constexpr float kOpaque = 1e-5f;

struct Pending {
    std::vector<std::size_t> pixel;  // which pixel each ray of the batch serves
    RayBatch rays;
    std::vector<double> travelled;   // planar depth already covered by each ray
};

}  // namespace

BufferPtr transparent(CaptureBackend& backend, const Camera& camera, const CaptureRequest& request,
                      const SampleShader& shadeCrossing, Color background, int maxCrossings, Context& ctx) {
    if (camera.width <= 0 || camera.height <= 0) throw Error("transparency reference: the camera's resolution must be positive");
    if (!shadeCrossing) throw Error("transparency reference: no shader given");
    if (maxCrossings < 1) throw Error("transparency reference: maxCrossings must be at least 1");
    const int w = camera.width, h = camera.height;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    std::vector<float> rgb(3 * n, 0.0f), transmit(n, 1.0f), crossings(n, 0.0f);
    Pending p;
    p.rays.reserve(n);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            Vec3 o, d;
            camera.ray(x + 0.5, y + 0.5, o, d);
            p.rays.add(o, d);
            p.pixel.push_back(std::size_t(y) * std::size_t(w) + std::size_t(x));
            p.travelled.push_back(0.0);
        }
    for (int round = 0; round < maxCrossings && p.rays.size() > 0; ++round) {
        const BufferPtr hits = backend.trace(p.rays, request, ctx);
        if (ctx.cancelled()) throw Cancelled();
        const float* t = hits->requireFloat("Z");
        Pending next;
        for (std::size_t r = 0; r < p.rays.size(); ++r) {
            if (!std::isfinite(t[r])) continue;
            const std::size_t i = p.pixel[r];
            float c[4] = {0, 0, 0, 0};
            shadeCrossing(*hits, r, c);  // straight colour and its opacity
            const float a = std::clamp(c[3], 0.0f, 1.0f);
            for (int k = 0; k < 3; ++k) rgb[3 * i + std::size_t(k)] += transmit[i] * a * c[k];
            transmit[i] *= 1.0f - a;
            crossings[i] += 1.0f;
            if (transmit[i] < kOpaque) continue;
            // Go on from just beyond this hit (t counts in units of the
            // direction, whose forward component is 1: planar depth).
            const double travelled = p.travelled[r] + double(t[r]);
            const double step = double(t[r]) + kSameSurface * std::max(travelled, 1e-30);
            const Vec3 o{p.rays.origins[3 * r], p.rays.origins[3 * r + 1], p.rays.origins[3 * r + 2]};
            const Vec3 d{p.rays.directions[3 * r], p.rays.directions[3 * r + 1], p.rays.directions[3 * r + 2]};
            next.rays.add(o + d * step, d);
            next.pixel.push_back(i);
            next.travelled.push_back(p.travelled[r] + step);
        }
        p = std::move(next);
        ctx.progress(double(round + 1) / maxCrossings);
    }
    auto out = ctx.allocate(w, h, {{"R"}, {"G"}, {"B"}, {"A"}, {"crossings"}});
    out->metadata().camera = camera;
    float* dst[4] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B"), out->writeFloat("A")};
    float* count = out->writeFloat("crossings");
    const float bg[3] = {background.r, background.g, background.b};
    for (std::size_t i = 0; i < n; ++i) {
        for (int k = 0; k < 3; ++k) dst[k][i] = rgb[3 * i + std::size_t(k)] + transmit[i] * bg[k];
        dst[3][i] = 1.0f;
        count[i] = crossings[i];
    }
    return out;
}

}  // namespace darkroom::reference
