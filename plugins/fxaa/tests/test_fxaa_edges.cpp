// The pass's vectorised path (contrast check, edge list, decisions a vector
// at a time) against the straightforward per-pixel FXAA: luma, decide() and
// the blend for every pixel in turn, on a picture that is mostly edges. The
// two must agree bit for bit, with every SIMD instruction set of the CPU.
#include "../../normals/tests/simd_targets.h"
#include "fxaa_helpers.h"
#include "src/fxaa_kernel.h"
#include "src/fxaa_presets.h"
#include "src/luma.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>

using namespace darkroom;
using namespace darkroom::test;

namespace {

// Thin lines and small discs with dark rims over a gradient, some running off
// the image; a few NaN, infinite and transparent pixels, and half-transparent
// discs (the premultiplied blend). Odd size: rows end inside a vector.
BufferPtr edgeHeavy(int w, int h) {
    return makeImage(w, h, {"R", "G", "B", "A"}, [&](int x, int y, int c) {
        const std::uint32_t hsh = std::uint32_t(x) * 73856093u ^ std::uint32_t(y) * 19349663u;
        if (hsh % 997u == 3u) return c == 3 ? 1.0f : kNaN;
        if (hsh % 991u == 5u) return c == 3 ? 1.0f : kInf;
        if (hsh % 983u == 7u) return c == 3 ? 0.0f : 0.7f;
        const double px = x + 0.5, py = y + 0.5;
        // Lines: x cos a + y sin a = d for a few angles, 1-3 px wide.
        for (int k = 0; k < 12; ++k) {
            const double a = 0.37 * k + 0.1, d = std::fmod(23.0 * k, double(w)), width = 1.0 + (k % 3);
            const double dist = std::fabs(px * std::cos(a) + py * std::sin(a) - d);
            if (dist < width) return c == 3 ? 1.0f : float(0.2 + 0.05 * k + 0.1 * c);
            if (dist < width + 1.0) return c == 3 ? 1.0f : 0.02f;
        }
        // Discs of radius 2-4 on a grid, every third one half transparent.
        const int cx = (x / 13) * 13 + 6, cy = (y / 11) * 11 + 5, r = 2 + int((cx + cy) % 3);
        const double dd = (px - cx) * (px - cx) + (py - cy) * (py - cy);
        if (dd < r * r) return c == 3 ? ((cx / 13) % 3 == 0 ? 0.5f : 1.0f) : (c == 0 ? 0.9f : 0.15f);
        return c == 3 ? 1.0f : float(0.3 + 0.4 * y / h);
    });
}

// FXAA one pixel at a time, as the pass computed it before any vectors.
BufferPtr perPixelFxaa(const Buffer& in, const std::string& presetName) {
    const int w = in.width(), h = in.height();
    const std::size_t n = in.pixelCount();
    const float* src[4] = {in.hostFloat("R"), in.hostFloat("G"), in.hostFloat("B"), in.hostFloat("A")};
    std::vector<float> luma(n);
    fxaa::computeLuma(src[0], src[1], src[2], src[3], luma.data(), 0, n);
    fxaa::Settings s;
    s.preset = &fxaa::preset(presetName);
    const fxaa::LumaPlane plane{luma.data(), w, h};
    auto out = makeImage(w, h, {"R", "G", "B", "A"}, [](int, int, int) { return 0.0f; });
    float* dst[4] = {out->writeFloat("R"), out->writeFloat("G"), out->writeFloat("B"), out->writeFloat("A")};
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const std::size_t i = std::size_t(y) * std::size_t(w) + std::size_t(x);
            for (int c = 0; c < 4; ++c) dst[c][i] = src[c][i];
            if (std::isnan(luma[i])) continue;
            const fxaa::Blend d = fxaa::decide(plane, x, y, s);
            const int nx = std::clamp(x + d.dx, 0, w - 1), ny = std::clamp(y + d.dy, 0, h - 1);
            const std::size_t j = std::size_t(ny) * std::size_t(w) + std::size_t(nx);
            if (!(d.amount > 0.0f) || j == i || std::isnan(luma[j])) continue;
            const float t = d.amount, *a = src[3];
            if (a[i] == a[j]) {
                for (int c = 0; c < 3; ++c) dst[c][i] = src[c][i] + t * (src[c][j] - src[c][i]);
                continue;
            }
            const float wi = a[i] * (1.0f - t), wj = a[j] * t, alpha = wi + wj;
            for (int c = 0; c < 3; ++c) dst[c][i] = (wi * src[c][i] + wj * src[c][j]) / alpha;
            dst[3][i] = alpha;
        }
    return out;
}

bool sameBits(const Buffer& a, const Buffer& b, std::string& where) {
    for (const char* c : {"R", "G", "B", "A"})
        for (std::size_t i = 0; i < a.pixelCount(); ++i)
            if (std::memcmp(a.hostFloat(c) + i, b.hostFloat(c) + i, sizeof(float)) != 0) {
                where = std::string(c) + " at pixel " + std::to_string(i);
                return false;
            }
    return true;
}

}  // namespace

TEST(FxaaEdges, VectorisedPathGivesThePerPixelBitsOnAnEdgeHeavyPicture) {
    const BufferPtr in = edgeHeavy(203, 157);
    for (const char* preset : {"10", "12", "24", "29", "39"}) {
        const BufferPtr reference = perPixelFxaa(*in, preset);
        EXPECT_FALSE(identical(*reference, *in)) << "preset " << preset << ": nothing to anti-alias";
        const auto results = resultsPerSimdTarget([&] { return runFxaa(in, {{"preset", {Value(preset)}}}); });
        for (const auto& [target, out] : results) {
            std::string where;
            EXPECT_TRUE(sameBits(*out, *reference, where)) << "preset " << preset << ", " << target << ": " << where;
        }
        std::string where;
        EXPECT_TRUE(sameBits(*runFxaa(in, {{"preset", {Value(preset)}}}, 1), *reference, where))
            << "preset " << preset << ", one thread: " << where;
    }
}

TEST(FxaaEdges, NarrowAndShortImagesGiveThePerPixelBits) {
    // Fewer pixels per row than a vector, and lists shorter than a vector.
    for (auto [w, h] : {std::pair{3, 40}, {17, 5}, {40, 3}, {1, 9}, {33, 2}}) {
        const BufferPtr in = edgeHeavy(w, h);
        std::string where;
        EXPECT_TRUE(sameBits(*runFxaa(in), *perPixelFxaa(*in, "12"), where)) << w << "x" << h << ": " << where;
    }
}
