// Scalable Ambient Obscurance (McGuire, Mara and Luebke, HPG 2012): taps on a
// spiral around the pixel read a rotated-grid depth chain at the level their
// distance asks for (level floor(log2 d) - 3 for a tap d pixels away), so a
// large radius touches as few cache lines as a small one.
//
// The estimator is McGuire's (Alchemy AO, HPG 2011) with its constants made
// exact: a visible pixel Q seen from the receiver C covers the solid angle
// dA cos(phi) / |v|^2 (v = Q - C, dA the surface element the tap stands for,
// phi the angle between Q's normal and v); cosine-weighted occlusion is
// (1/pi) sum of (v.n / |v|) times that. Taps uniform in radius (McGuire's
// spiral) make a tap's screen area 2 pi rho h / s (rho its distance, h the
// radius in pixels, s the taps); so each tap adds
//   2 rho h / s * pixelSize(Q)^2 * (|cos phi| / |cos psi|) * v.n / |v|^3,
// psi the angle between Q's normal and its view ray (dA = projected area /
// cos psi). With rho ~ |v|, equal depths and cos phi ~ cos psi this is
// McGuire's 2/s * v.n / v.v with sigma = R. Counting the visible surface and
// not a height field makes it right for thin geometry (a particle or a line
// occludes by what it covers) and for a wall, wrong where hidden geometry
// occludes (the far side of a hill) or occluders overlap as seen from C
// (counted twice, then clamped).
#include "ao_estimators.h"
#include "scalar_pixel.h"

#include <algorithm>
#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

namespace darkroom::ssao {
namespace {

constexpr double kGoldenAngle = 2.39996322972865332;  // pi (3 - sqrt 5): any tap count spreads evenly
constexpr int kLogMaxOffset = 3;  // McGuire's q': taps within 2^3 px read level 0
// Below this |cos psi| a pixel's normal is too unreliable (silhouettes) to
// scale its area by; the cap keeps one grazing pixel from dominating.
constexpr float kMinCosPsi = 0.5f;

// The spiral's fixed angles, rotated per pixel by one sine/cosine pair.
struct Spiral {
    std::vector<float> c, s;
    explicit Spiral(int taps) : c(std::size_t(taps)), s(std::size_t(taps)) {
        for (int i = 0; i < taps; ++i) {
            c[std::size_t(i)] = float(std::cos(double(i) * kGoldenAngle));
            s[std::size_t(i)] = float(std::sin(double(i) * kGoldenAngle));
        }
    }
};

float saoPixel(const Frame& g, const Pyramid& pyr, const AoSettings& s, const Spiral& spiral, int x, int y) {
    Receiver r;
    if (!makeReceiver(g, pyr.levels[0], s, x, y, r)) return 1.0f;
    const float h = r.R / r.pixelSize;  // radius in pixels
    if (h < 1.0f) return 1.0f;          // nothing resolvable, as horizon
    const V3f origin = r.p + r.n * (s.bias * r.R);
    const int taps = s.samples, top = int(pyr.levels.size()) - 1, width0 = pyr.levels[0].width;
    const float W = float(g.width()), H = float(g.height()), R2 = r.R * r.R;
    const float px = float(x) + 0.5f, py = float(y) + 0.5f;
    const float spin = 2.0f * std::numbers::pi_v<float> * r.spin;
    const float cs = std::cos(spin), sn = std::sin(spin);
    const float tapArea = 2.0f * h / float(taps);  // times rho: a tap's share of the disc, in pixels^2
    float occlusion = 0;
    for (int i = 0; i < taps; ++i) {
        // Radius uniform within each of the s rings (jittered per pixel):
        // McGuire's alpha_i = (i + 0.5) / s, made unbiased.
        const float rho = (float(i) + r.jitter) / float(taps) * h;
        const float ci = spiral.c[std::size_t(i)], si = spiral.s[std::size_t(i)];
        const float tx = px + rho * (cs * ci - sn * si), ty = py + rho * (sn * ci + cs * si);
        if (!(tx >= 0 && ty >= 0 && tx < W && ty < H)) continue;  // off screen: unknown, not an occluder
        // Level floor(log2 rho) - 3: a texel of level m spans 2^m pixels,
        // at most an eighth of the tap's distance.
        const int m = std::clamp(int(std::bit_width(unsigned(rho))) - 1 - kLogMaxOffset, 0, top);
        const PyramidLevel& L = pyr.levels[std::size_t(m)];
        const std::size_t at = L.at(std::min(int(tx) >> m, L.width - 1), std::min(int(ty) >> m, L.height - 1));
        const float zq = L.z[at];
        if (!(zq < std::numeric_limits<float>::infinity())) continue;  // background never occludes
        const std::uint32_t src = L.source[at];
        const V3f q = positionAt(g, float(src % unsigned(width0)) + 0.5f, float(src / unsigned(width0)) + 0.5f, zq);
        const V3f v = q - origin;
        const float vn = dot(v, r.n), d2 = dot(v, v);
        if (vn <= 0 || !(d2 < R2) || d2 <= 0) continue;
        const float d = std::sqrt(d2);
        const float w = distanceWeight(d, r.R, s.falloff);
        const V3f nq{L.n[0][at], L.n[1][at], L.n[2][at]};
        const V3f view = g.perspective() ? q * (-1.0f / length(q)) : V3f{0, 0, -1};
        const float cosPsi = std::max(std::fabs(dot(nq, view)), kMinCosPsi);
        const float cosPhi = std::fabs(dot(nq, v)) / d;
        const float ps = pixelSizeAt(g, zq);
        occlusion += w * tapArea * rho * ps * ps * (cosPhi / cosPsi) * vn / (d2 * d);
    }
    return std::clamp(1.0f - occlusion, 0.0f, 1.0f);
}

}  // namespace

void saoAO(const Frame& g, const Pyramid& p, const AoSettings& s, int y, const std::int32_t* xs, int count, float* ao) {
    const Spiral spiral(s.samples);
    const std::size_t row = g.offset(0, y);
    if (!xs) {
        for (int x = 0; x < g.width(); ++x) ao[row + std::size_t(x)] = saoPixel(g, p, s, spiral, x, y);
        return;
    }
    for (int i = 0; i < count; ++i) ao[row + std::size_t(xs[i])] = saoPixel(g, p, s, spiral, xs[i], y);
}

}  // namespace darkroom::ssao
