#include "sphere_raster.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom::spheres {

namespace {

// Extent of the sphere's silhouette along one image axis at unit depth: the
// two tangents from the eye to the circle (c_a, c_z) of radius r in the plane
// spanned by that axis and the view direction.
void tangentRange(double ca, double cz, double r, double& lo, double& hi) {
    const double d2 = ca * ca + cz * cz - r * r;
    const double root = r * std::sqrt(std::max(0.0, d2));
    const double den = cz * cz - r * r;
    lo = (ca * cz - root) / den;
    hi = (ca * cz + root) / den;
}

// A continuous pixel bound brought within a few pixels of [0, n] before it
// becomes an int: through a narrow camera a sphere just in front of the eye
// has bounds near ±10^10, past any int. NaN (from infinities in the
// tangents) bounds nothing: `fallback`, the image edge on that side.
double clampedBound(double v, int n, double fallback) {
    return std::isnan(v) ? fallback : std::clamp(v, -2.0, double(n) + 2.0);
}

}  // namespace

bool screenBounds(const Camera& cam, const Sphere& s, double& x0, double& y0, double& x1, double& y1) {
    Vec3 right, up, fwd;
    cam.basis(right, up, fwd);
    const Vec3 rel = s.center - cam.position;
    const double cx = dot(rel, right), cy = dot(rel, up), cz = dot(rel, fwd);
    const double hh = cam.halfHeight();
    const double hw = hh * double(cam.width) / double(cam.height > 0 ? cam.height : 1);
    double sx0, sx1, sy0, sy1;
    if (cam.projection == Camera::Projection::Perspective) {
        if (cz + s.radius <= 0) return false;  // wholly behind the eye
        if (cz - s.radius <= 1e-9 * std::max(1.0, s.radius)) {
            x0 = y0 = 0;
            x1 = cam.width;
            y1 = cam.height;
            return true;
        }
        tangentRange(cx, cz, s.radius, sx0, sx1);
        tangentRange(cy, cz, s.radius, sy0, sy1);
    } else {
        sx0 = cx - s.radius;
        sx1 = cx + s.radius;
        sy0 = cy - s.radius;
        sy1 = cy + s.radius;
    }
    // Camera::planeOffsets inverted: sx = (2 px / w - 1) hw, sy = (1 - 2 py / h) hh.
    x0 = (sx0 / hw + 1) * 0.5 * cam.width;
    x1 = (sx1 / hw + 1) * 0.5 * cam.width;
    y0 = (1 - sy1 / hh) * 0.5 * cam.height;
    y1 = (1 - sy0 / hh) * 0.5 * cam.height;
    return true;
}

double intersect(const Vec3& o, const Vec3& d, const Sphere& s) {
    const Vec3 oc = o - s.center;
    const double a = dot(d, d), b = dot(d, oc), c = dot(oc, oc) - s.radius * s.radius;
    const double disc = b * b - a * c;
    if (disc < 0) return -1;
    const double root = std::sqrt(disc);
    // The numerically stable pair of roots.
    const double q = b > 0 ? -(b + root) : -(b - root);
    double t0 = q / a, t1 = q != 0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > 0) return t0;
    return t1 > 0 ? t1 : -1;  // the eye inside the sphere sees its far side
}

Hits castSpheres(Context& ctx, const Camera& cam, const std::vector<Sphere>& spheres) {
    const int w = cam.width, h = cam.height;
    const std::size_t n = std::size_t(w) * std::size_t(h);
    Hits hits;
    hits.depth.assign(n, std::numeric_limits<float>::infinity());
    hits.index.assign(n, -1);
    for (auto& c : hits.normal) c.assign(n, std::numeric_limits<float>::quiet_NaN());

    // Pixel rectangles, and the spheres whose rectangle meets each band of rows.
    constexpr int kBand = 16;
    const int bands = (h + kBand - 1) / kBand;
    struct Box {
        int x0, y0, x1, y1;  // inclusive pixel ranges, clipped
    };
    std::vector<Box> boxes(spheres.size());
    std::vector<std::vector<int>> perBand(std::size_t(std::max(bands, 0)));
    for (std::size_t i = 0; i < spheres.size(); ++i) {
        double fx0, fy0, fx1, fy1;
        if (!(spheres[i].radius > 0) || !screenBounds(cam, spheres[i], fx0, fy0, fx1, fy1)) continue;
        fx0 = clampedBound(fx0, w, -2.0);
        fy0 = clampedBound(fy0, h, -2.0);
        fx1 = clampedBound(fx1, w, w + 2.0);
        fy1 = clampedBound(fy1, h, h + 2.0);
        // Pixels whose centre may fall inside, with one pixel to spare for rounding.
        const Box b{std::max(0, int(std::floor(fx0 - 0.5)) - 1), std::max(0, int(std::floor(fy0 - 0.5)) - 1),
                    std::min(w - 1, int(std::ceil(fx1 - 0.5)) + 1), std::min(h - 1, int(std::ceil(fy1 - 0.5)) + 1)};
        if (b.x0 > b.x1 || b.y0 > b.y1) continue;
        boxes[i] = b;
        for (int band = b.y0 / kBand; band <= b.y1 / kBand; ++band) perBand[std::size_t(band)].push_back(int(i));
    }

    // Camera::ray's arithmetic with the basis and the per-column and per-row
    // image-plane offsets computed once (ray() re-derives the basis per call).
    Vec3 right, up, fwd;
    cam.basis(right, up, fwd);
    const bool perspective = cam.projection == Camera::Projection::Perspective;
    std::vector<double> sxs(std::size_t(std::max(w, 0))), sys(std::size_t(std::max(h, 0)));
    for (int x = 0; x < w; ++x) {
        double sy;
        cam.planeOffsets(x + 0.5, 0.5, sxs[std::size_t(x)], sy);
    }
    for (int y = 0; y < h; ++y) {
        double sx;
        cam.planeOffsets(0.5, y + 0.5, sx, sys[std::size_t(y)]);
    }
    auto rayAt = [&](int x, int y, Vec3& o, Vec3& d) {
        const double sx = sxs[std::size_t(x)], sy = sys[std::size_t(y)];
        if (perspective) {
            o = cam.position;
            d = fwd + right * sx + up * sy;
        } else {
            o = cam.position + right * sx + up * sy;
            d = fwd;
        }
    };

    ctx.parallelFor(0, bands, 1, [&](int band0, int band1) {
        for (int band = band0; band < band1; ++band) {
            const int yEnd = std::min(h, (band + 1) * kBand);
            for (int i : perBand[std::size_t(band)]) {
                const Box& b = boxes[std::size_t(i)];
                const Sphere& s = spheres[std::size_t(i)];
                for (int y = std::max(b.y0, band * kBand); y <= std::min(b.y1, yEnd - 1); ++y)
                    for (int x = b.x0; x <= b.x1; ++x) {
                        Vec3 o, d;
                        rayAt(x, y, o, d);
                        const double t = intersect(o, d, s);
                        if (!(t > 0)) continue;
                        const std::size_t p = std::size_t(y) * std::size_t(w) + std::size_t(x);
                        const float depth = float(t);
                        // Nearest wins; on equal depth the lower index (spheres are visited in index order).
                        if (!(depth < hits.depth[p])) continue;
                        hits.depth[p] = depth;
                        hits.index[p] = i;
                        const Vec3 nrm = (o + d * t - s.center) * (1.0 / s.radius);
                        hits.normal[0][p] = float(nrm.x);
                        hits.normal[1][p] = float(nrm.y);
                        hits.normal[2][p] = float(nrm.z);
                    }
            }
        }
    });
    return hits;
}

}  // namespace darkroom::spheres
