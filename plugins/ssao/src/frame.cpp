// Frame: depth planes and normals, SIMD over the pixels of a row.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "frame.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep

#include "frame.h"
#include "simd-inl.h"

#include <darkroom/error.h>

#include <hwy/highway.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

HWY_BEFORE_NAMESPACE();
namespace darkroom::ssao::HWY_NAMESPACE {

// Row y of the padded planes, from the input's depth row (width floats).
void SanitizeRow(const Frame& g, const float* zin, int y, bool wantInverse) {
    const DF d;
    const int N = int(hn::Lanes(d));
    const float inf = std::numeric_limits<float>::infinity();
    float* z = g.z + std::size_t(y + g.padY) * std::size_t(g.stride);
    float* f = wantInverse ? g.f + std::size_t(y + g.padY) * std::size_t(g.stride) : nullptr;
    if (y < 0 || y >= g.height() || !zin) {
        std::fill(z, z + g.stride, inf);
        if (f) std::fill(f, f + g.stride, -inf);
        return;
    }
    std::fill(z, z + g.padX, inf);
    if (f) std::fill(f, f + g.padX, -inf);
    z += g.padX;
    if (f) f += g.padX;
    const bool persp = g.perspective();
    const VF vinf = hn::Set(d, inf), vninf = hn::Set(d, -inf), one = hn::Set(d, 1.0f);
    int x = 0;
    for (; x + N <= g.width(); x += N) {
        const VF v = hn::LoadU(d, zin + x);
        MF ok = hn::IsFinite(v);
        if (persp) ok = hn::And(ok, hn::Gt(v, hn::Zero(d)));
        hn::Store(hn::IfThenElse(ok, v, vinf), d, z + x);
        if (f) hn::Store(hn::IfThenElse(ok, persp ? hn::Div(one, v) : v, vninf), d, f + x);
    }
    for (; x < g.width(); ++x) {
        const float v = zin[x];
        const bool ok = std::isfinite(v) && (!persp || v > 0);
        z[x] = ok ? v : inf;
        if (f) f[x] = ok ? (persp ? 1.0f / v : v) : -inf;
    }
    std::fill(z + g.width(), z + (g.stride - g.padX), inf);
    if (f) std::fill(f + g.width(), f + (g.stride - g.padX), -inf);
}

// View-space position of pixels x .. x + N - 1 of the row whose image-plane y
// is sy, at depth z (non-finite depths give non-finite positions).
HWY_INLINE V3 Position(DF d, const Frame& g, VF px, VF sy, VF z) {
    const VF sx = hn::MulAdd(px, hn::Set(d, g.ax), hn::Set(d, g.bx));
    if (g.perspective()) return {hn::Mul(sx, z), hn::Mul(sy, z), z};
    return {sx, sy, z};
}

// Tangent along one axis from the centre c and its neighbours a (before) and b
// (after): the difference towards the neighbour with the smaller depth jump.
// `has` is false where neither neighbour is a surface.
HWY_INLINE V3 SideDifference(VF zc, VF za, VF zb, V3 pc, V3 pa, V3 pb, MF& has) {
    const DF d;
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const MF a = hn::Lt(za, inf), b = hn::Lt(zb, inf);
    has = hn::Or(a, b);
    const MF closerB = hn::Le(hn::Abs(hn::Sub(zb, zc)), hn::Abs(hn::Sub(zc, za)));
    const MF useB = hn::And(b, hn::Or(hn::Not(a), closerB));
    return Select(useB, Sub(pb, pc), Sub(pc, pa));
}

void NormalRow(const Frame& g, int y, const float* const world[3], const float* toView) {
    const DF d;
    const int N = int(hn::Lanes(d));
    const std::size_t row = g.offset(0, y);
    const std::size_t up = row - std::size_t(g.stride), down = row + std::size_t(g.stride);
    const float* z = g.z;
    const VF inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const VF syC = hn::Set(d, g.ay * (float(y) + 0.5f) + g.by);
    const VF syU = hn::Set(d, g.ay * (float(y) - 0.5f) + g.by);
    const VF syD = hn::Set(d, g.ay * (float(y) + 1.5f) + g.by);
    const VF half = hn::Set(d, 0.5f), one = hn::Set(d, 1.0f);
    for (int x = 0; x < g.width(); x += N) {
        const VF zc = hn::Load(d, z + row + x);
        const MF valid = hn::Lt(zc, inf);
        float* out[3] = {g.n[0] + row + x, g.n[1] + row + x, g.n[2] + row + x};
        if (hn::AllFalse(d, valid)) {
            for (auto* o : out) hn::Store(hn::Zero(d), d, o);
            continue;
        }
        const VF px = hn::Add(hn::ConvertTo(d, hn::Add(hn::Iota(DI(), 0), hn::Set(DI(), x))), half);
        const V3 pc = Position(d, g, px, syC, zc);
        V3 v = g.perspective() ? Normalize(d, Scale(pc, hn::Set(d, -1.0f))) : Splat(d, 0, 0, -1);
        V3 nrm{hn::Zero(d), hn::Zero(d), hn::Zero(d)};
        MF have = hn::FirstN(d, 0);
        if (world) {
            const std::size_t at = std::size_t(y) * std::size_t(g.width()) + std::size_t(x);
            const float nan = std::numeric_limits<float>::quiet_NaN();
            const VF wx = LoadPartial(d, world[0] + at, g.width() - x, nan);
            const VF wy = LoadPartial(d, world[1] + at, g.width() - x, nan);
            const VF wz = LoadPartial(d, world[2] + at, g.width() - x, nan);
            have = hn::And(hn::IsFinite(wx), hn::And(hn::IsFinite(wy), hn::IsFinite(wz)));
            const V3 nv{hn::MulAdd(wx, hn::Set(d, toView[0]), hn::MulAdd(wy, hn::Set(d, toView[3]), hn::Mul(wz, hn::Set(d, toView[6])))),
                        hn::MulAdd(wx, hn::Set(d, toView[1]), hn::MulAdd(wy, hn::Set(d, toView[4]), hn::Mul(wz, hn::Set(d, toView[7])))),
                        hn::MulAdd(wx, hn::Set(d, toView[2]), hn::MulAdd(wy, hn::Set(d, toView[5]), hn::Mul(wz, hn::Set(d, toView[8]))))};
            nrm = Select(have, Normalize(d, nv), nrm);
        }
        if (!hn::AllTrue(d, hn::Or(have, hn::Not(valid)))) {
            const VF zl = hn::LoadU(d, z + row + x - 1), zr = hn::LoadU(d, z + row + x + 1);
            const VF zu = hn::Load(d, z + up + x), zd = hn::Load(d, z + down + x);
            MF hasX, hasY;
            const V3 ddx = SideDifference(zc, zl, zr, pc, Position(d, g, hn::Sub(px, one), syC, zl),
                                          Position(d, g, hn::Add(px, one), syC, zr), hasX);
            const V3 ddy = SideDifference(zc, zu, zd, pc, Position(d, g, px, syU, zu), Position(d, g, px, syD, zd), hasY);
            // Image y runs down; the sign is fixed below.
            const V3 rec = Normalize(d, Cross(ddx, ddy));
            nrm = Select(have, nrm, Select(hn::And(hasX, hasY), rec, V3{hn::Zero(d), hn::Zero(d), hn::Zero(d)}));
        }
        // An isolated pixel (or a degenerate normal) faces the camera.
        nrm = Select(hn::Gt(Dot(nrm, nrm), half), nrm, v);
        nrm = Select(hn::Lt(Dot(nrm, v), hn::Zero(d)), Scale(nrm, hn::Set(d, -1.0f)), nrm);
        hn::Store(hn::IfThenElseZero(valid, nrm.x), d, out[0]);
        hn::Store(hn::IfThenElseZero(valid, nrm.y), d, out[1]);
        hn::Store(hn::IfThenElseZero(valid, nrm.z), d, out[2]);
    }
}

}  // namespace darkroom::ssao::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::ssao {

HWY_EXPORT(SanitizeRow);
HWY_EXPORT(NormalRow);

Frame::Frame(const Camera& camera, int width, int height, int border) : ViewGeometry(camera, width, height) {
    constexpr int kAlign = 16;  // floats: one AVX-512 vector, 64 bytes
    auto roundUp = [](int v, int m) { return (v + m - 1) / m * m; };
    padY = std::max(border, 1);
    padX = roundUp(std::max(border, 1), kAlign);
    stride = padX + roundUp(width, kAlign) + padX;
    // Gathers index planes with 32-bit offsets.
    if (double(height + 2 * padY) * double(stride) >= double(std::numeric_limits<std::int32_t>::max()))
        throw Error("SSAO: the image is too large (at most about 2^31 pixels)");
    ax = 2.0f * halfWidth() / float(width);
    bx = -halfWidth();
    ay = -2.0f * halfHeight() / float(height);
    by = halfHeight();
    pixelScale = 2.0f * halfHeight() / float(height);
}

std::shared_ptr<WritableBuffer> Frame::allocatePlanes(Context& ctx, int count) const {
    std::vector<ChannelDesc> channels;
    for (int i = 0; i < count; ++i) channels.push_back({"plane" + std::to_string(i), ChannelType::Float32});
    return ctx.allocate(stride, height() + 2 * padY, std::move(channels), Fill::None);
}

void Frame::fillPadding(float* plane, int y0, int y1, float value) const {
    for (int y = y0; y < y1; ++y) {
        float* row = plane + std::size_t(y + padY) * std::size_t(stride);
        if (y < 0 || y >= height()) {
            std::fill(row, row + stride, value);
        } else {
            std::fill(row, row + padX, value);
            std::fill(row + padX + width(), row + stride, value);
        }
    }
}

Frame buildFrame(const Buffer& in, const Camera& camera, bool useNormals, int border, Context& ctx) {
    Frame g(camera, in.width(), in.height(), border);
    g.storage = g.allocatePlanes(ctx, 5);
    g.z = g.storage->writeFloat("plane0");
    g.f = g.storage->writeFloat("plane1");
    for (int c = 0; c < 3; ++c) g.n[c] = g.storage->writeFloat("plane" + std::to_string(c + 2));
    const float* z = in.requireFloat("Z");
    const int rows = g.height() + 2 * g.padY;
    ctx.parallelFor(0, rows, 32, [&](int r0, int r1) {
        for (int r = r0; r < r1; ++r) {
            const int y = r - g.padY;
            const bool inside = y >= 0 && y < g.height();
            HWY_DYNAMIC_DISPATCH(SanitizeRow)(g, inside ? z + std::size_t(y) * std::size_t(g.width()) : nullptr, y,
                                              true);
            if (!inside)
                for (float* p : g.n) std::fill(p + std::size_t(r) * g.stride, p + std::size_t(r + 1) * g.stride, 0.0f);
        }
    });

    const float* nx = useNormals ? in.hostFloat("N.x") : nullptr;
    const float* ny = useNormals ? in.hostFloat("N.y") : nullptr;
    const float* nz = useNormals ? in.hostFloat("N.z") : nullptr;
    const bool haveNormals = nx && ny && nz;
    if (useNormals && !haveNormals)
        ctx.warn("useNormals is set but the image has no N.x/N.y/N.z; normals are reconstructed from Z");
    const float* world[3] = {nx, ny, nz};
    // Row i of the matrix: the view-space image of world axis i.
    float toView[9];
    for (int i = 0; i < 3; ++i) {
        const V3f c = g.toView(Vec3{i == 0 ? 1.0 : 0.0, i == 1 ? 1.0 : 0.0, i == 2 ? 1.0 : 0.0});
        toView[3 * i] = c.x, toView[3 * i + 1] = c.y, toView[3 * i + 2] = c.z;
    }
    ctx.parallelFor(0, g.height(), 16, [&](int y0, int y1) {
        for (int y = y0; y < y1; ++y) {
            float* rowStart[3];
            for (int c = 0; c < 3; ++c) rowStart[c] = g.n[c] + std::size_t(y + g.padY) * g.stride;
            for (auto* p : rowStart) std::fill(p, p + g.padX, 0.0f);
            HWY_DYNAMIC_DISPATCH(NormalRow)(g, y, haveNormals ? world : nullptr, toView);
            const int end = g.padX + (g.width() + 15) / 16 * 16;
            for (auto* p : rowStart) std::fill(p + end, p + g.stride, 0.0f);
        }
    });
    return g;
}

}  // namespace darkroom::ssao
#endif  // HWY_ONCE
