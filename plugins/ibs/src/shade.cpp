#include "shade.h"

#include <algorithm>
#include <cmath>

namespace darkroom::passes {

void ShadeJob::setView(const Camera& camera) {
    camera.basis(right, up, forward);
    perspective = camera.projection == Camera::Projection::Perspective;
    sx.resize(std::size_t(width));
    sy.resize(std::size_t(height));
    double unused;
    for (int x = 0; x < width; ++x) camera.planeOffsets(x + 0.5, 0.5, sx[std::size_t(x)], unused);
    for (int y = 0; y < height; ++y) camera.planeOffsets(0.5, y + 0.5, unused, sy[std::size_t(y)]);
}

void shadeAt(const ShadeJob& job, int x, int y) {
    const std::size_t i = std::size_t(y) * std::size_t(job.width) + std::size_t(x);
    double v[3] = {job.rgb[0][i], job.rgb[1][i], job.rgb[2][i]};
    if (job.lighting()) {
        // The view-space normal in single precision, as the Normals pass stores it.
        float nv[3];
        if (job.worldNormals) {
            const Vec3 n{job.normal[0][i], job.normal[1][i], job.normal[2][i]};
            nv[0] = float(dot(n, job.right));
            nv[1] = float(dot(n, job.up));
            nv[2] = float(dot(n, job.forward));
        } else {
            for (int k = 0; k < 3; ++k) nv[k] = job.normal[k][i];
        }
        // Unit vector to the eye in view space (z forward, so the eye is at -z).
        const Vec3 eye = job.perspective ? normalize(Vec3{-job.sx[std::size_t(x)], -job.sy[std::size_t(y)], -1})
                                         : Vec3{0, 0, -1};
        const double d = nv[0] * eye.x + nv[1] * eye.y + nv[2] * eye.z;
        // Headlight L = ambient + (1 - ambient) max(0, N.V). NaN normals (no
        // surface, or NaN in captured N) leave the colour alone: lighting
        // touches surfaces only.
        const float light = float(job.ambient + (1.0 - job.ambient) * std::max(0.0, d));
        if (!std::isnan(d))
            for (double& c : v) c *= job.luminance * light;
    }
    // Straight-alpha "over" of the outline colour with opacity k.
    const double k = job.strength * double(job.color.a) * job.silhouette[i];
    const double a = job.alpha ? job.alpha[i] : 1.0;
    const double ao = k + a * (1.0 - k);
    const float c[3] = {job.color.r, job.color.g, job.color.b};
    for (int ch = 0; ch < 3; ++ch)
        job.out[ch][i] = ao > 0 ? float((c[ch] * k + v[ch] * a * (1.0 - k)) / ao) : float(v[ch]);
    if (job.outAlpha) job.outAlpha[i] = float(ao);
}

void shade(Context& ctx, const ShadeJob& job) {
    ctx.parallelFor(0, job.height, 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = shadeRow(job, y); x < job.width; ++x) shadeAt(job, x, y);
    });
}

}  // namespace darkroom::passes
