#include "coc.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace darkroom::ssdof {

// Thin lens of diameter A focused at depth zf. The cone of rays from a point at
// depth z through the lens cuts the focal plane in a disc of diameter
//   C = A |z - zf| / z            (similar triangles; independent of focal length)
// and the focal plane is imaged sharply, so C measured in pixels of that plane
// is the blur on the image: one pixel there is h*zf wide (h = pixelPerDepth =
// 2 tan(fovY/2) / imageHeight). The signed radius is therefore
//   r = C / (2 h zf) * sign(z - zf) = A / (2 h) * (1/zf - 1/z),
// which stays finite for z -> inf (A / (2 h zf), the far-field limit the
// background takes) and for zf -> inf (focus at infinity: -A / (2 h z)).
// An orthographic camera has no lens: we put one at the camera plane and use
// the constant pixel size, r = A / (2 h) * (1/zf - 1/z) with h the pixel size,
// i.e. the same expression with zf*h replaced by the constant footprint.
float LensModel::signedRadius(float z) const {
    const double invZ = (z > 0.0f && std::isfinite(z)) ? 1.0 / double(z) : 0.0;
    const double invF = std::isfinite(focalDistance) ? 1.0 / focalDistance : 0.0;
    if (aperture <= 0.0 || pixelPerDepth <= 0.0) return 0.0f;
    double r = 0.0;
    if (orthographic)
        r = aperture / (2.0 * pixelPerDepth) * (invF - invZ) * (std::isfinite(focalDistance) ? focalDistance : 1.0);
    else
        r = aperture / (2.0 * pixelPerDepth) * (invF - invZ);
    if (std::isnan(r)) return 0.0f;
    return float(std::clamp(r, -maxBlur, maxBlur));
}

LensModel makeLens(const Camera& camera, int imageHeight, double aperture, double focalDistance,
                   double maxBlur) {
    if (imageHeight <= 0) throw Error("the image has no rows");
    LensModel lens;
    lens.aperture = aperture;
    lens.focalDistance = focalDistance;
    lens.maxBlur = maxBlur;
    lens.orthographic = camera.projection == Camera::Projection::Orthographic;
    // pixelSizeAt(1) uses the camera's own height; the buffer's is authoritative.
    lens.pixelPerDepth = 2.0 * camera.halfHeight() / double(imageHeight);
    if (!(lens.pixelPerDepth > 0.0) || !std::isfinite(lens.pixelPerDepth))
        throw Error("the camera's field of view (or view height) must be positive and finite");
    return lens;
}

double autoFocusDistance(const float* z, int width, int height) {
    std::vector<float> v;
    const int cx = width / 2, cy = height / 2;
    for (int y = std::max(0, cy - 2); y <= std::min(height - 1, cy + 2); ++y)
        for (int x = std::max(0, cx - 2); x <= std::min(width - 1, cx + 2); ++x) {
            const float d = z[std::size_t(y) * std::size_t(width) + std::size_t(x)];
            if (d > 0.0f && std::isfinite(d)) v.push_back(d);
        }
    if (v.empty()) return std::numeric_limits<double>::infinity();
    std::sort(v.begin(), v.end());
    return v.size() % 2 ? v[v.size() / 2] : 0.5 * (double(v[v.size() / 2 - 1]) + v[v.size() / 2]);
}

}  // namespace darkroom::ssdof
