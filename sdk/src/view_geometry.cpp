#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace darkroom {

Camera requireCamera(const Buffer& in, const std::string& what) {
    if (!in.metadata().camera)
        throw Error(what + " carries no camera in its metadata; depth-based passes need the camera "
                           "that produced the depth (capture with Darkroom, read an EXR that has one, or "
                           "set one with a Camera node)");
    Camera c = *in.metadata().camera;
    c.width = in.width();
    c.height = in.height();
    return c;
}

namespace {

// Per-column and per-row image-plane offsets in double precision, so the
// inner loop does no trigonometry or basis orthonormalisation.
struct PlaneOffsets {
    Vec3 right, up, forward;
    bool perspective = true;
    std::vector<double> sx, sy;
    double pixelSize = 0;  // orthographic pixel size (world units)

    PlaneOffsets(const Camera& c, int w, int h) : sx(std::size_t(w)), sy(std::size_t(h)) {
        c.basis(right, up, forward);
        perspective = c.projection == Camera::Projection::Perspective;
        double dummy;
        for (int x = 0; x < w; ++x) c.planeOffsets(x + 0.5, 0.5, sx[std::size_t(x)], dummy);
        for (int y = 0; y < h; ++y) c.planeOffsets(0.5, y + 0.5, dummy, sy[std::size_t(y)]);
        pixelSize = c.pixelSizeAt(1.0);
    }

    // View-space position of a pixel centre (x right, y up, z forward).
    Vec3 viewPosition(int x, int y, double z) const {
        const double a = sx[std::size_t(x)], b = sy[std::size_t(y)];
        return perspective ? Vec3{z * a, z * b, z} : Vec3{a, b, z};
    }
    // The quantity that is affine in image coordinates on a plane.
    double affine(double z) const { return perspective ? 1.0 / z : z; }
    Vec3 toWorld(const Vec3& v) const { return right * v.x + up * v.y + forward * v.z; }
};

struct AxisSamples {
    bool l1, l2, r1, r2;  // neighbours present (inside and on a surface)
    double zl1, zl2, zr1, zr2;
};

enum class Side { Central, Left, Right, None };

Side chooseSide(NormalMethod m, const AxisSamples& s, double zc, const PlaneOffsets& g) {
    if (!s.l1 && !s.r1) return Side::None;
    if (!s.l1) return Side::Right;
    if (!s.r1) return Side::Left;
    if (m == NormalMethod::Central) return Side::Central;
    if (m == NormalMethod::Extrapolated && s.l2 && s.r2) {
        const double ac = g.affine(zc);
        const double el = std::abs(2.0 * g.affine(s.zl1) - g.affine(s.zl2) - ac);
        const double er = std::abs(2.0 * g.affine(s.zr1) - g.affine(s.zr2) - ac);
        // Both sides agree up to rounding or curvature: the central difference
        // is the more accurate one there.
        const double eps = 1e-5 * (std::abs(ac) + (g.perspective ? 0.0 : g.pixelSize));
        if (std::max(el, er) <= 2.0 * std::min(el, er) + eps) return Side::Central;
        return el < er ? Side::Left : Side::Right;
    }
    // Nearest (and Extrapolated without two neighbours on each side).
    return std::abs(s.zl1 - zc) < std::abs(s.zr1 - zc) ? Side::Left : Side::Right;
}

}  // namespace

void reconstructNormals(Context& ctx, const float* depth, int w, int h, const Camera& camera, NormalMethod method,
                        const NormalOutputs& out) {
    const PlaneOffsets g(camera, w, h);
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double zSign = out.viewZTowardsViewer ? -1.0 : 1.0;
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < w; ++x) {
                const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
                const float zc = depth[i];
                auto put = [&](float* const* dst, const Vec3& v) {
                    if (dst[0]) dst[0][i] = float(v.x);
                    if (dst[1]) dst[1][i] = float(v.y);
                    if (dst[2]) dst[2][i] = float(v.z);
                };
                if (!isSurface(zc)) {
                    put(out.view, {nan, nan, nan});
                    put(out.world, {nan, nan, nan});
                    put(out.position, {nan, nan, nan});
                    continue;
                }
                auto sample = [&](int xx, int yy, bool& ok, double& z) {
                    ok = xx >= 0 && yy >= 0 && xx < w && yy < h;
                    if (ok) {
                        const float v = depth[std::size_t(yy) * std::size_t(w) + std::size_t(xx)];
                        ok = isSurface(v);
                        z = v;
                    }
                };
                const Vec3 pc = g.viewPosition(x, y, zc);
                // Tangent along one image axis (dx, dy) = (1, 0) or (0, 1).
                auto tangent = [&](int dx, int dy, const Vec3& fallback) {
                    AxisSamples s{};
                    sample(x - dx, y - dy, s.l1, s.zl1);
                    sample(x - 2 * dx, y - 2 * dy, s.l2, s.zl2);
                    sample(x + dx, y + dy, s.r1, s.zr1);
                    sample(x + 2 * dx, y + 2 * dy, s.r2, s.zr2);
                    switch (chooseSide(method, s, zc, g)) {
                        case Side::Central:
                            return g.viewPosition(x + dx, y + dy, s.zr1) - g.viewPosition(x - dx, y - dy, s.zl1);
                        case Side::Left: return pc - g.viewPosition(x - dx, y - dy, s.zl1);
                        case Side::Right: return g.viewPosition(x + dx, y + dy, s.zr1) - pc;
                        case Side::None: break;
                    }
                    return fallback;
                };
                const Vec3 tx = tangent(1, 0, {1, 0, 0});
                const Vec3 ty = tangent(0, 1, {0, -1, 0});  // image y runs down
                const Vec3 toViewer = g.perspective ? -pc : Vec3{0, 0, -1};
                // z forward makes this frame left-handed: tx x ty is the
                // normal on the viewer's side.
                Vec3 n = cross(tx, ty);
                const double len = length(n);
                n = len > 0 && std::isfinite(len) ? n * (1.0 / len) : normalize(toViewer);
                if (dot(n, toViewer) < 0) n = -n;  // visible surfaces face the camera
                put(out.view, {n.x, n.y, zSign * n.z});
                if (out.world[0] || out.world[1] || out.world[2]) put(out.world, g.toWorld(n));
                if (out.position[0] || out.position[1] || out.position[2])
                    put(out.position, camera.position + g.toWorld(pc));
            }
    });
}

void worldToViewNormals(Context& ctx, const float* const world[3], std::size_t count, const Camera& camera,
                        float* const view[3], bool zTowardsViewer) {
    Vec3 r, u, f;
    camera.basis(r, u, f);
    const int rows = int((count + 4095) / 4096);
    ctx.parallelFor(0, rows, 4, [&](int b, int e) {
        for (std::size_t i = std::size_t(b) * 4096; i < std::min(count, std::size_t(e) * 4096); ++i) {
            const Vec3 n{world[0][i], world[1][i], world[2][i]};
            view[0][i] = float(dot(n, r));
            view[1][i] = float(dot(n, u));
            view[2][i] = float(zTowardsViewer ? -dot(n, f) : dot(n, f));
        }
    });
}

}  // namespace darkroom
