#include "pixel_geometry.h"

#include <algorithm>
#include <cmath>

namespace darkroom::ssao {

namespace {

// Difference vector to the neighbour along one axis: the side with the
// smaller depth jump, or nothing when neither neighbour is valid.
bool sideDifference(const PixelGeometry& g, const float* z, int x, int y, int dx, int dy, V3f& out) {
    const std::size_t c = g.index(x, y);
    const int xa = x - dx, ya = y - dy, xb = x + dx, yb = y + dy;
    const bool a = xa >= 0 && ya >= 0 && g.valid[g.index(xa, ya)];
    const bool b = xb < g.width() && yb < g.height() && g.valid[g.index(xb, yb)];
    if (!a && !b) return false;
    bool useB = b;
    if (a && b) useB = std::fabs(z[g.index(xb, yb)] - z[c]) <= std::fabs(z[c] - z[g.index(xa, ya)]);
    out = useB ? g.points[g.index(xb, yb)] - g.points[c] : g.points[c] - g.points[g.index(xa, ya)];
    return true;
}

}  // namespace

bool PixelGeometry::surfaceAt(float px, float py, V3f& out) const {
    const std::size_t nearest = index(int(px), int(py));
    const float fx = px - 0.5f, fy = py - 0.5f;
    // Clamped so that the outer half pixel at the borders is extrapolated from
    // the two outermost rows/columns (still exact for a plane).
    const int x0 = std::clamp(int(std::floor(fx)), 0, width() - 2), y0 = std::clamp(int(std::floor(fy)), 0, height() - 2);
    if (width() >= 2 && height() >= 2) {
        const std::size_t i00 = index(x0, y0), i10 = i00 + 1, i01 = i00 + std::size_t(width()), i11 = i01 + 1;
        if (valid[i00] && valid[i10] && valid[i01] && valid[i11]) {
            const float z00 = points[i00].z, z10 = points[i10].z, z01 = points[i01].z, z11 = points[i11].z;
            const float lo = std::min(std::min(z00, z10), std::min(z01, z11));
            const float hi = std::max(std::max(z00, z10), std::max(z01, z11));
            // Depth spread of at most 4 pixel sizes: a smooth surface up to
            // ~70 degrees from facing the camera; more is taken as an edge,
            // across which interpolation would invent surface points.
            if (hi - lo <= 4.0f * pixelSizeAt(lo)) {
                const float tx = fx - float(x0), ty = fy - float(y0);
                auto f = [&](float z) { return perspective() ? 1.0f / z : z; };
                const float top = f(z00) + (f(z10) - f(z00)) * tx, bottom = f(z01) + (f(z11) - f(z01)) * tx;
                const float v = top + (bottom - top) * ty;
                out = unproject(px, py, perspective() ? 1.0f / v : v);
                return true;
            }
        }
    }
    if (!valid[nearest]) return false;
    out = points[nearest];
    return true;
}

PixelGeometry buildPixelGeometry(const Buffer& in, const Camera& camera, bool useNormals, Context& ctx) {
    PixelGeometry g(camera, in.width(), in.height());
    const std::size_t n = in.pixelCount();
    g.points.resize(n);
    g.normal.resize(n);
    g.valid.assign(n, 0);
    const float* z = in.requireFloat("Z");

    ctx.parallelFor(0, g.height(), 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < g.width(); ++x) {
                const std::size_t i = g.index(x, y);
                const float d = z[i];
                const bool ok = std::isfinite(d) && (!g.perspective() || d > 0);
                g.valid[i] = ok;
                g.points[i] = ok ? g.position(x, y, d) : V3f{};
            }
    });

    const float* nx = useNormals ? in.hostFloat("N.x") : nullptr;
    const float* ny = useNormals ? in.hostFloat("N.y") : nullptr;
    const float* nz = useNormals ? in.hostFloat("N.z") : nullptr;
    const bool haveNormals = nx && ny && nz;
    if (useNormals && !haveNormals)
        ctx.warn("useNormals is set but the image has no N.x/N.y/N.z; normals are reconstructed from Z");
    ctx.parallelFor(0, g.height(), 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < g.width(); ++x) {
                const std::size_t i = g.index(x, y);
                if (!g.valid[i]) continue;
                const V3f v = g.toCamera(g.points[i]);
                V3f nrm{};
                if (haveNormals && std::isfinite(nx[i]) && std::isfinite(ny[i]) && std::isfinite(nz[i])) {
                    nrm = normalize(g.toView(Vec3{nx[i], ny[i], nz[i]}));
                } else {
                    V3f ddx, ddy;
                    // Image y runs down; the cross product's sign is fixed below.
                    if (sideDifference(g, z, x, y, 1, 0, ddx) && sideDifference(g, z, x, y, 0, 1, ddy))
                        nrm = normalize(cross(ddx, ddy));
                }
                if (!(dot(nrm, nrm) > 0.5f)) nrm = v;  // isolated pixel: face the camera
                if (dot(nrm, v) < 0) nrm = nrm * -1.0f;
                g.normal[i] = nrm;
            }
    });
    return g;
}

}  // namespace darkroom::ssao
