#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include "normals_kernel.h"

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

namespace normals {

PlaneOffsets::PlaneOffsets(const Camera& c, int w, int h)
    : origin(c.position), sx(std::size_t(w)), sy(std::size_t(h)) {
    c.basis(right, up, forward);
    perspective = c.projection == Camera::Projection::Perspective;
    double dummy;
    for (int x = 0; x < w; ++x) c.planeOffsets(x + 0.5, 0.5, sx[std::size_t(x)], dummy);
    for (int y = 0; y < h; ++y) c.planeOffsets(0.5, y + 0.5, dummy, sy[std::size_t(y)]);
    pixelSize = c.pixelSizeAt(1.0);
}

namespace {

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

void normalAt(const Job& job, int x, int y) {
    const int w = job.width, h = job.height;
    const PlaneOffsets& g = *job.plane;
    const NormalOutputs& out = job.out;
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const double zSign = out.viewZTowardsViewer ? -1.0 : 1.0;
    const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
    const float zc = job.depth[i];
    auto put = [&](float* const* dst, const Vec3& v) {
        if (dst[0]) dst[0][i] = float(v.x);
        if (dst[1]) dst[1][i] = float(v.y);
        if (dst[2]) dst[2][i] = float(v.z);
    };
    if (!isSurface(zc)) {
        put(out.view, {nan, nan, nan});
        put(out.world, {nan, nan, nan});
        put(out.position, {nan, nan, nan});
        return;
    }
    auto sample = [&](int xx, int yy, bool& ok, double& z) {
        ok = xx >= 0 && yy >= 0 && xx < w && yy < h;
        if (ok) {
            const float v = job.depth[std::size_t(yy) * std::size_t(w) + std::size_t(xx)];
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
        switch (chooseSide(job.method, s, zc, g)) {
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
    // z forward makes this frame left-handed: tx x ty is the normal on the
    // viewer's side.
    Vec3 n = cross(tx, ty);
    const double len = length(n);
    n = len > 0 && std::isfinite(len) ? n * (1.0 / len) : normalize(toViewer);
    if (dot(n, toViewer) < 0) n = -n;  // visible surfaces face the camera
    put(out.view, {n.x, n.y, zSign * n.z});
    if (out.world[0] || out.world[1] || out.world[2]) put(out.world, g.toWorld(n));
    if (out.position[0] || out.position[1] || out.position[2]) put(out.position, g.origin + g.toWorld(pc));
}

}  // namespace normals

void reconstructNormals(Context& ctx, const float* depth, int w, int h, const Camera& camera, NormalMethod method,
                        const NormalOutputs& out) {
    const normals::PlaneOffsets g(camera, w, h);
    const normals::Job job{depth, w, h, &g, method, out};
    const bool extrapolated = method == NormalMethod::Extrapolated;
    ctx.parallelFor(0, h, 8, [&](int y0, int y1) {
        // The affine depth of rows y - 2 .. y + 2, computed once per row and
        // kept in a ring of five rows.
        std::vector<double> ring(extrapolated ? 5 * std::size_t(w) : 0);
        auto affineRow = [&](int yy) { return ring.data() + std::size_t((yy % 5 + 5) % 5) * std::size_t(w); };
        auto fillRow = [&](int yy) {
            if (yy < 0 || yy >= h) return;
            double* a = affineRow(yy);
            const float* row = depth + std::size_t(yy) * std::size_t(w);
            for (int x = 0; x < w; ++x) a[x] = g.affine(row[x]);
        };
        if (extrapolated)
            for (int yy = y0 - 2; yy < y0 + 2; ++yy) fillRow(yy);
        for (int y = y0; y < y1; ++y) {
            const double* affine[5] = {nullptr, nullptr, nullptr, nullptr, nullptr};
            if (extrapolated) {
                fillRow(y + 2);
                for (int k = 0; k < 5; ++k)
                    if (y - 2 + k >= 0 && y - 2 + k < h) affine[k] = affineRow(y - 2 + k);
            }
            const int left = std::min(2, w), right = std::max(left, w - 2);
            int x = 0;
            for (; x < left; ++x) normals::normalAt(job, x, y);
            if (right > left) x = normals::normalsSpan(job, y, left, right, affine);
            for (; x < w; ++x) normals::normalAt(job, x, y);
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
