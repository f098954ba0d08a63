// Ray-traced ambient occlusion: primary hits from the backend's render(), then
// `samples` occlusion rays per pixel through occluded().
#include "sampling.h"

#include <darkroom/context.h>
#include <darkroom/error.h>
#include <darkroom/accuracy/reference.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace darkroom::reference {

const char* toString(AoWeighting w) { return w == AoWeighting::Cosine ? "cosine" : "uniform"; }

namespace {

// Rays per occluded() call: bounds memory (about 30 bytes a ray) while
// keeping batches large enough to spread over every thread.
constexpr std::size_t kRaysPerBatch = std::size_t(1) << 21;

bool usable(float z, const float* n[3], std::size_t i) {
    return std::isfinite(z) && z > 0.0f && std::isfinite(n[0][i]) && std::isfinite(n[1][i]) &&
           std::isfinite(n[2][i]);
}

}  // namespace

BufferPtr ambientOcclusion(CaptureBackend& backend, const Camera& camera, const AoOptions& options, Context& ctx) {
    if (options.samples < 1)
        throw Error("reference AO: samples is " + std::to_string(options.samples) + "; expected at least 1");
    if (!(options.radius > 0.0) || !std::isfinite(options.radius))
        throw Error("reference AO: the radius must be positive and finite");

    CaptureRequest request;
    request.normals = true;
    const BufferPtr gbuffer = backend.render(camera, request, ctx);
    const int w = gbuffer->width(), h = gbuffer->height();
    const float* z = gbuffer->requireFloat("Z");
    const float* n[3] = {gbuffer->requireFloat("N.x"), gbuffer->requireFloat("N.y"), gbuffer->requireFloat("N.z")};

    auto out = ctx.allocate(w, h, {{"Z"}, {"AO"}, {"AO.stderr"}});
    out->metadata().camera = camera;
    out->metadata().attributes["units.Z"] = "world";
    out->metadata().attributes["reference.AO"] =
        std::string(toString(options.weighting)) + ", " + std::to_string(options.samples) + " rays per pixel";
    float* zo = out->writeFloat("Z");
    float* ao = out->writeFloat("AO");
    float* se = out->writeFloat("AO.stderr");
    std::copy(z, z + gbuffer->pixelCount(), zo);

    const std::size_t samples = std::size_t(options.samples);
    const int rowsPerBatch = int(std::max<std::size_t>(1, kRaysPerBatch / (samples * std::size_t(w))));
    RayBatch rays;
    std::vector<std::uint8_t> hit;
    std::vector<std::size_t> rowStart(std::size_t(rowsPerBatch) + 1);
    for (int y0 = 0; y0 < h; y0 += rowsPerBatch) {
        const int y1 = std::min(h, y0 + rowsPerBatch);
        // Rays only for pixels that have a surface; a prefix count per row
        // lets the rows fill the batch in parallel.
        rowStart[0] = 0;
        for (int y = y0; y < y1; ++y) {
            std::size_t count = 0;
            for (int x = 0; x < w; ++x) count += usable(z[std::size_t(y) * w + x], n, std::size_t(y) * w + x);
            rowStart[std::size_t(y - y0) + 1] = rowStart[std::size_t(y - y0)] + count * samples;
        }
        const std::size_t total = rowStart[std::size_t(y1 - y0)];
        rays.origins.resize(3 * total);
        rays.directions.resize(3 * total);
        rays.tFar.resize(total);
        rays.tNear = 0.0f;
        ctx.parallelFor(y0, y1, 1, [&](int ya, int yb) {
            for (int y = ya; y < yb; ++y) {
                std::size_t r = rowStart[std::size_t(y - y0)];
                for (int x = 0; x < w; ++x) {
                    const std::size_t i = std::size_t(y) * w + x;
                    if (!usable(z[i], n, i)) continue;
                    const Vec3 p = camera.worldPosition(x + 0.5, y + 0.5, z[i]);
                    const Vec3 nn = normalize(Vec3{n[0][i], n[1][i], n[2][i]});
                    const double radius =
                        options.radiusInImageHeights ? options.radius * h * camera.pixelSizeAt(z[i]) : options.radius;
                    // Lift the origin off the surface by a few hundred float
                    // ulps of the coordinates, so a ray does not hit the
                    // triangle it starts on; tiny against any radius used.
                    const double scale = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z), double(z[i])});
                    const Vec3 origin = p + nn * (3e-5 * scale);
                    Vec3 t, b;
                    detail::tangents(nn, t, b);
                    for (std::size_t s = 0; s < samples; ++s, ++r) {
                        const double u1 = detail::uniform(i, std::uint32_t(s), options.seed, 0);
                        const double u2 = detail::uniform(i, std::uint32_t(s), options.seed, 1);
                        const Vec3 l = options.weighting == AoWeighting::Cosine ? detail::cosineHemisphere(u1, u2)
                                                                                : detail::uniformHemisphere(u1, u2);
                        const Vec3 d = t * l.x + b * l.y + nn * l.z;
                        rays.origins[3 * r] = float(origin.x), rays.origins[3 * r + 1] = float(origin.y),
                        rays.origins[3 * r + 2] = float(origin.z);
                        rays.directions[3 * r] = float(d.x), rays.directions[3 * r + 1] = float(d.y),
                        rays.directions[3 * r + 2] = float(d.z);
                        rays.tFar[r] = float(radius);
                    }
                }
            }
        });
        if (total > 0) backend.occluded(rays, hit, ctx);
        if (ctx.cancelled()) throw Cancelled();
        ctx.parallelFor(y0, y1, 4, [&](int ya, int yb) {
            for (int y = ya; y < yb; ++y) {
                std::size_t r = rowStart[std::size_t(y - y0)];
                for (int x = 0; x < w; ++x) {
                    const std::size_t i = std::size_t(y) * w + x;
                    if (!usable(z[i], n, i)) {
                        // Background is unoccluded; a hit without a usable
                        // normal has no hemisphere.
                        const bool background = !(std::isfinite(z[i]) && z[i] > 0.0f);
                        ao[i] = background ? 1.0f : std::numeric_limits<float>::quiet_NaN();
                        se[i] = background ? 0.0f : std::numeric_limits<float>::quiet_NaN();
                        continue;
                    }
                    std::size_t occluded = 0;
                    for (std::size_t s = 0; s < samples; ++s, ++r) occluded += hit[r];
                    const double p = 1.0 - double(occluded) / double(samples);
                    ao[i] = float(p);
                    // Visibility is 0 or 1, so the sample variance is
                    // p (1 - p) N / (N - 1) and the standard error of the
                    // mean sqrt(p (1 - p) / (N - 1)).
                    se[i] = samples > 1 ? float(std::sqrt(p * (1.0 - p) / double(samples - 1)))
                                        : std::numeric_limits<float>::quiet_NaN();
                }
            }
        });
    }
    ctx.progress(1.0);
    return out;
}

}  // namespace darkroom::reference
