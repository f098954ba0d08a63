// Image-comparison metrics against values known from their definitions.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/accuracy/metrics.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using namespace darkroom;
using namespace darkroom::metrics;

namespace {

constexpr float kNaNf = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();
constexpr double kPi = 3.14159265358979323846;

// A deterministic, non-trivial image with values k/256 in [0, 1): exact in float,
// so x + c for c = 1/4 is exact too.
std::vector<float> pattern(int w, int h) {
    std::vector<float> v(std::size_t(w) * std::size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) v[std::size_t(y * w + x)] = float(((x * 37 + y * 91 + x * y * 13) % 193)) / 256.0f;
    return v;
}

// Straightforward SSIM of Wang et al. 2004 in double precision: for every window
// fully inside the image, a 2D (non-separable) normalised Gaussian, the weighted
// means, variances and covariance, then the formula; the mean over windows.
double referenceSsim(const std::vector<float>& a, const std::vector<float>& b, int w, int h, double L = 1.0) {
    double g[11][11];
    double gsum = 0.0;
    for (int j = 0; j < 11; ++j)
        for (int i = 0; i < 11; ++i) {
            g[j][i] = std::exp(-((i - 5) * (i - 5) + (j - 5) * (j - 5)) / (2.0 * 1.5 * 1.5));
            gsum += g[j][i];
        }
    const double c1 = (0.01 * L) * (0.01 * L), c2 = (0.03 * L) * (0.03 * L);
    double total = 0.0;
    int windows = 0;
    for (int oy = 0; oy + 11 <= h; ++oy)
        for (int ox = 0; ox + 11 <= w; ++ox) {
            double ma = 0, mb = 0;
            for (int j = 0; j < 11; ++j)
                for (int i = 0; i < 11; ++i) {
                    const double wt = g[j][i] / gsum;
                    ma += wt * a[std::size_t((oy + j) * w + ox + i)];
                    mb += wt * b[std::size_t((oy + j) * w + ox + i)];
                }
            double va = 0, vb = 0, cab = 0;
            for (int j = 0; j < 11; ++j)
                for (int i = 0; i < 11; ++i) {
                    const double wt = g[j][i] / gsum;
                    const double da = a[std::size_t((oy + j) * w + ox + i)] - ma;
                    const double db = b[std::size_t((oy + j) * w + ox + i)] - mb;
                    va += wt * da * da;
                    vb += wt * db * db;
                    cab += wt * da * db;
                }
            total += ((2 * ma * mb + c1) * (2 * cab + c2)) / ((ma * ma + mb * mb + c1) * (va + vb + c2));
            ++windows;
        }
    return total / windows;
}

// Weighted window means, for the closed form of SSIM(x, x + c).
std::vector<double> windowMeans(const std::vector<float>& a, int w, int h) {
    double g[11];
    double s = 0;
    for (int i = 0; i < 11; ++i) s += g[i] = std::exp(-(i - 5) * (i - 5) / (2.0 * 1.5 * 1.5));
    std::vector<double> out;
    for (int oy = 0; oy + 11 <= h; ++oy)
        for (int ox = 0; ox + 11 <= w; ++ox) {
            double m = 0;
            for (int j = 0; j < 11; ++j)
                for (int i = 0; i < 11; ++i) m += g[j] * g[i] / (s * s) * a[std::size_t((oy + j) * w + ox + i)];
            out.push_back(m);
        }
    return out;
}

}  // namespace

TEST(Metrics, ConstantOffsetGivesKnownRmsePsnrAndBias) {
    const int w = 16, h = 16;
    const std::vector<float> a = pattern(w, h);
    for (float d : {0.25f, -0.125f}) {
        std::vector<float> b(a);
        for (float& v : b) v += d;
        const Measure r = rmse(a.data(), b.data(), a.size());
        EXPECT_DOUBLE_EQ(r.value, std::abs(d));
        EXPECT_EQ(r.count, a.size());
        EXPECT_EQ(r.skipped, 0u);
        EXPECT_NEAR(psnr(a.data(), b.data(), a.size()).value, 20.0 * std::log10(1.0 / std::abs(d)), 1e-12);
        EXPECT_NEAR(psnr(a.data(), b.data(), a.size(), 255.0).value, 20.0 * std::log10(255.0 / std::abs(d)), 1e-12);
        // bias is mean(a - b): b = a + d gives -d, and swapping gives +d.
        EXPECT_DOUBLE_EQ(bias(a.data(), b.data(), a.size()).value, -double(d));
        EXPECT_DOUBLE_EQ(bias(b.data(), a.data(), a.size()).value, double(d));
    }
    EXPECT_EQ(rmse(a.data(), a.data(), a.size()).value, 0.0);
    EXPECT_EQ(psnr(a.data(), a.data(), a.size()).value, std::numeric_limits<double>::infinity());
}

TEST(Metrics, NaNPixelsAreSkippedAndCounted) {
    std::vector<float> a(10, 0.5f), b(10, 0.5f);
    b[9] = 1.5f;                            // the only real difference: 1.0
    a[1] = kNaNf, a[2] = kNaNf, b[2] = kNaNf, b[3] = kNaNf;  // 3 pixels touched
    const Measure r = rmse(a.data(), b.data(), a.size());
    EXPECT_EQ(r.count, 7u);
    EXPECT_EQ(r.skipped, 3u);
    EXPECT_DOUBLE_EQ(r.value, std::sqrt(1.0 / 7.0));
    EXPECT_DOUBLE_EQ(bias(a.data(), b.data(), a.size()).value, -1.0 / 7.0);
    // A mask selecting pixels 0..3: one used, three skipped.
    const std::uint8_t mask[10] = {1, 1, 1, 1, 0, 0, 0, 0, 0, 0};
    const Measure m = rmse(a.data(), b.data(), a.size(), mask);
    EXPECT_EQ(m.count, 1u);
    EXPECT_EQ(m.skipped, 3u);
    EXPECT_EQ(m.value, 0.0);
    // Nothing usable: NaN, count 0.
    const std::uint8_t only1[10] = {0, 1, 0, 0, 0, 0, 0, 0, 0, 0};
    const Measure none = psnr(a.data(), b.data(), a.size(), 1.0, only1);
    EXPECT_EQ(none.count, 0u);
    EXPECT_EQ(none.skipped, 1u);
    EXPECT_TRUE(std::isnan(none.value));
}

TEST(Metrics, BufferOverloadsReadTheChannelAndCheckSizes) {
    auto a = test::makeImage(8, 4, {"R", "G"}, [](int x, int, int c) { return c ? float(x) : 0.0f; });
    auto b = test::makeImage(8, 4, {"R", "G"}, [](int x, int, int c) { return c ? float(x) + 0.5f : 0.0f; });
    EXPECT_DOUBLE_EQ(rmse(*a, *b, "G").value, 0.5);
    EXPECT_DOUBLE_EQ(bias(*a, *b, "G").value, -0.5);
    EXPECT_EQ(rmse(*a, *b, "R").value, 0.0);
    EXPECT_NEAR(psnr(*a, *b, "G", 2.0).value, 20.0 * std::log10(4.0), 1e-12);
    auto c = test::makeImage(4, 4, {"G"}, [](int, int, int) { return 0.0f; });
    EXPECT_THROW(rmse(*a, *c, "G"), Error);
    EXPECT_THROW(rmse(*a, *b, "B"), Error);
}

TEST(Metrics, SsimOfAnImageWithItselfIsExactlyOne) {
    const int w = 16, h = 16;
    const std::vector<float> a = pattern(w, h);
    const Measure s = ssim(a.data(), a.data(), w, h);
    EXPECT_EQ(s.value, 1.0);
    EXPECT_EQ(s.count, 36u);  // (16-10) x (16-10) valid windows
    EXPECT_EQ(ssimMap(a.data(), a.data(), w, h).size(), 36u);
}

TEST(Metrics, SsimOfAConstantShiftIsTheLuminanceTermOnly) {
    const int w = 16, h = 16;
    const std::vector<float> a = pattern(w, h);
    for (double L : {1.0, 0.5}) {
        const float c = 0.25f;
        std::vector<float> b(a);
        for (float& v : b) v += c;  // exact in float
        // Variances and covariance are unchanged by a shift, so the contrast-structure
        // term is 1 and each window contributes (2 mu (mu+c) + C1) / (mu^2 + (mu+c)^2 + C1).
        const double c1 = (0.01 * L) * (0.01 * L);
        double want = 0;
        const std::vector<double> mu = windowMeans(a, w, h);
        for (double m : mu) want += (2 * m * (m + c) + c1) / (m * m + (m + c) * (m + c) + c1);
        want /= double(mu.size());
        EXPECT_NEAR(ssim(a.data(), b.data(), w, h, L).value, want, 1e-12) << "L = " << L;
        EXPECT_LT(want, 1.0);
    }
}

TEST(Metrics, SsimMatchesAStraightforwardImplementation) {
    const int w = 16, h = 19;
    const std::vector<float> a = pattern(w, h);
    std::vector<float> neg(a), noisy(a), flat(a.size(), 0.3f);
    for (float& v : neg) v = 1.0f - v;
    for (std::size_t i = 0; i < noisy.size(); ++i) noisy[i] += float((i * 7919) % 17) / 128.0f - 0.0625f;
    for (const auto* b : {&neg, &noisy, &flat}) {
        const double want = referenceSsim(a, *b, w, h);
        const Measure got = ssim(a.data(), b->data(), w, h);
        EXPECT_NEAR(got.value, want, 1e-12);
        EXPECT_EQ(got.count, 6u * 9u);
    }
    // The negative is strongly anti-correlated: SSIM is negative.
    EXPECT_LT(referenceSsim(a, neg, w, h), 0.0);
    EXPECT_NEAR(ssim(a.data(), noisy.data(), w, h, 255.0).value, referenceSsim(a, noisy, w, h, 255.0), 1e-12);
}

TEST(Metrics, SsimSkipsWindowsWithNaNAndHonoursTheMask) {
    const int w = 24, h = 24;
    std::vector<float> a = pattern(w, h), b = pattern(w, h);
    for (float& v : b) v *= 0.5f;
    const std::vector<double> map = ssimMap(a.data(), b.data(), w, h);
    ASSERT_EQ(map.size(), 14u * 14u);
    // Mask on pixel (5+3, 5+2): exactly the window at map position (3, 2).
    std::vector<std::uint8_t> mask(std::size_t(w * h), 0);
    mask[std::size_t(7 * w + 8)] = 1;
    const Measure one = ssim(a.data(), b.data(), w, h, 1.0, mask.data());
    EXPECT_EQ(one.count, 1u);
    EXPECT_EQ(one.value, map[2 * 14 + 3]);
    // A NaN at (2, 2) lies in the windows with offsets 0..2 in each direction: 9 windows.
    a[std::size_t(2 * w + 2)] = kNaNf;
    const Measure s = ssim(a.data(), b.data(), w, h);
    EXPECT_EQ(s.skipped, 9u);
    EXPECT_EQ(s.count, 196u - 9u);
    EXPECT_TRUE(std::isfinite(s.value));
    // Too small for one window.
    EXPECT_EQ(ssim(a.data(), b.data(), 10, 10).count, 0u);
}

namespace {

struct Field {
    std::vector<float> x, y, z;
    NormalField ptrs() const { return {x.data(), y.data(), z.data()}; }
};

// Unit normals spread over a hemisphere.
Field normals(std::size_t n) {
    Field f;
    for (std::size_t i = 0; i < n; ++i) {
        const double th = 0.1 + 1.3 * double(i % 13) / 13.0, ph = 2 * kPi * double(i % 29) / 29.0;
        f.x.push_back(float(std::sin(th) * std::cos(ph)));
        f.y.push_back(float(std::sin(th) * std::sin(ph)));
        f.z.push_back(float(std::cos(th)));
    }
    return f;
}

// Rotates each normal by deg(i) degrees about an axis perpendicular to it
// (Rodrigues), so the angle between them is exactly deg(i).
template <class F>
Field rotated(const Field& f, F deg) {
    Field r;
    for (std::size_t i = 0; i < f.x.size(); ++i) {
        const double n[3] = {f.x[i], f.y[i], f.z[i]};
        // axis = normalize(n x (1, 2, 3)), perpendicular to n.
        double k[3] = {n[1] * 3 - n[2] * 2, n[2] * 1 - n[0] * 3, n[0] * 2 - n[1] * 1};
        const double kl = std::sqrt(k[0] * k[0] + k[1] * k[1] + k[2] * k[2]);
        for (double& v : k) v /= kl;
        const double t = deg(i) * kPi / 180.0;
        const double kxn[3] = {k[1] * n[2] - k[2] * n[1], k[2] * n[0] - k[0] * n[2], k[0] * n[1] - k[1] * n[0]};
        // k . n = 0, so R n = n cos t + (k x n) sin t.
        r.x.push_back(float(n[0] * std::cos(t) + kxn[0] * std::sin(t)));
        r.y.push_back(float(n[1] * std::cos(t) + kxn[1] * std::sin(t)));
        r.z.push_back(float(n[2] * std::cos(t) + kxn[2] * std::sin(t)));
    }
    return r;
}

}  // namespace

TEST(Metrics, AngularErrorOfATenDegreeRotation) {
    const Field a = normals(400);
    const Field b = rotated(a, [](std::size_t) { return 10.0; });
    const AngularStats s = angularError(a.ptrs(), b.ptrs(), 400);
    EXPECT_EQ(s.count, 400u);
    EXPECT_EQ(s.skipped, 0u);
    EXPECT_NEAR(s.mean, 10.0, 1e-4);
    EXPECT_NEAR(s.median, 10.0, 1e-4);
    EXPECT_NEAR(s.p95, 10.0, 1e-4);
    EXPECT_EQ(s.shareAbove5, 1.0);
    // Identical fields: exactly zero (and scaling a vector changes nothing).
    Field scaled = a;
    for (float& v : scaled.x) v *= 2.0f;
    for (float& v : scaled.y) v *= 2.0f;
    for (float& v : scaled.z) v *= 2.0f;
    const AngularStats z = angularError(a.ptrs(), a.ptrs(), 400);
    EXPECT_EQ(z.mean, 0.0);
    EXPECT_EQ(z.shareAbove5, 0.0);
    EXPECT_NEAR(angularError(a.ptrs(), scaled.ptrs(), 400).p95, 0.0, 1e-5);
}

TEST(Metrics, AngularErrorPercentilesAndSkipping) {
    // Pixel i rotated by i degrees for i = 0..100 (pixel 5 by 4.999, off the
    // 5-degree boundary that float rounding could put on either side): mean 50,
    // median 50, p95 95, 95 of 101 above 5 degrees.
    const Field a = normals(101);
    Field b = rotated(a, [](std::size_t i) { return i == 5 ? 4.999 : double(i); });
    AngularStats s = angularError(a.ptrs(), b.ptrs(), 101);
    EXPECT_NEAR(s.mean, (5050.0 - 0.001) / 101.0, 1e-4);
    EXPECT_NEAR(s.median, 50.0, 1e-4);
    EXPECT_NEAR(s.p95, 95.0, 1e-4);
    EXPECT_DOUBLE_EQ(s.shareAbove5, 95.0 / 101.0);
    // p95 of an even count interpolates: 0..99 -> rank 94.05 -> 94.05 degrees.
    s = angularError(a.ptrs(), b.ptrs(), 100);
    EXPECT_NEAR(s.p95, 94.05, 1e-4);
    EXPECT_NEAR(s.median, 49.5, 1e-4);
    // NaN, infinite and zero-length (background) pixels are skipped and counted.
    Field c = a;
    c.x[100] = kNaNf;
    c.z[99] = kInf;
    b.y[98] = kNaNf;
    c.x[97] = c.y[97] = c.z[97] = 0.0f;
    s = angularError(c.ptrs(), b.ptrs(), 101);
    EXPECT_EQ(s.count, 97u);
    EXPECT_EQ(s.skipped, 4u);
    EXPECT_NEAR(s.median, 48.0, 1e-4);  // 0..96
    // Masked to the first 11 pixels (0..10 degrees).
    std::vector<std::uint8_t> mask(101, 0);
    for (int i = 0; i <= 10; ++i) mask[std::size_t(i)] = 1;
    s = angularError(c.ptrs(), b.ptrs(), 101, mask.data());
    EXPECT_EQ(s.count, 11u);
    EXPECT_NEAR(s.mean, (55.0 - 0.001) / 11.0, 1e-4);
    EXPECT_DOUBLE_EQ(s.shareAbove5, 5.0 / 11.0);
    // Buffers with the default N.x/N.y/N.z channels.
    auto ba = test::makeImage(101, 1, {"N.x", "N.y", "N.z"}, [&](int x, int, int k) {
        return (k == 0 ? a.x : k == 1 ? a.y : a.z)[std::size_t(x)];
    });
    const Field r10 = rotated(a, [](std::size_t) { return 10.0; });
    auto bb = test::makeImage(101, 1, {"N.x", "N.y", "N.z"}, [&](int x, int, int k) {
        return (k == 0 ? r10.x : k == 1 ? r10.y : r10.z)[std::size_t(x)];
    });
    EXPECT_NEAR(angularError(*ba, *bb).median, 10.0, 1e-4);
}

namespace {

std::vector<int> edgeColumns(const EdgeMasks& m, int row) {
    std::vector<int> cols;
    for (int x = 0; x < m.width; ++x)
        if (m.edge[std::size_t(row * m.width + x)]) cols.push_back(x);
    return cols;
}

}  // namespace

TEST(Metrics, EdgeMaskOfADepthStepIsTheTwoColumnsBesideIt) {
    const int w = 10, h = 6;
    // Step between columns 4 and 5 (1 -> 2); a gentle slope (1% per column) elsewhere.
    std::vector<float> z(std::size_t(w * h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) z[std::size_t(y * w + x)] = (x < 5 ? 1.0f : 2.0f) * (1.0f + 0.01f * float(x));
    const EdgeMasks m = edgeMasks(z.data(), nullptr, w, h);
    for (int y = 0; y < h; ++y) EXPECT_EQ(edgeColumns(m, y), (std::vector<int>{4, 5})) << "row " << y;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            EXPECT_EQ(m.interior[std::size_t(y * w + x)], (x == 4 || x == 5) ? 0 : 1) << x << "," << y;
    // A higher threshold ignores the step (relative jump ~ 1.0).
    const EdgeMasks none = edgeMasks(z.data(), nullptr, w, h, 1.5);
    for (auto e : none.edge) EXPECT_EQ(e, 0);

    // Background (+inf) on the right: the same two columns; background is not interior.
    for (int y = 0; y < h; ++y)
        for (int x = 5; x < w; ++x) z[std::size_t(y * w + x)] = kInf;
    const EdgeMasks bg = edgeMasks(z.data(), nullptr, w, h);
    for (int y = 0; y < h; ++y) EXPECT_EQ(edgeColumns(bg, y), (std::vector<int>{4, 5}));
    for (int x = 0; x < w; ++x) EXPECT_EQ(bg.interior[std::size_t(x)], x < 4 ? 1 : 0) << x;
}

TEST(Metrics, EdgeMaskOfAnIdChangeAndSplitStatistics) {
    const int w = 7, h = 7;
    // Constant depth; a single pixel with another id at (3, 3): the 3x3 block around it.
    auto g = makeCpuBuffer(w, h, {{"Z"}, {"objectId", ChannelType::UInt32}});
    float* z = g->writeFloat("Z");
    std::uint32_t* id = g->writeUInt("objectId");
    for (int i = 0; i < w * h; ++i) z[i] = 3.0f, id[i] = 1;
    id[3 * w + 3] = 2;
    const EdgeMasks m = edgeMasks(*g);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool near = std::abs(x - 3) <= 1 && std::abs(y - 3) <= 1;
            EXPECT_EQ(m.edge[std::size_t(y * w + x)], near ? 1 : 0) << x << "," << y;
            EXPECT_EQ(m.interior[std::size_t(y * w + x)], near ? 0 : 1) << x << "," << y;
        }
    // Ignoring ids: no edges.
    const EdgeMasks noIds = edgeMasks(*g, "Z", "");
    for (auto e : noIds.edge) EXPECT_EQ(e, 0);

    // Error 0.5 on the 9 edge pixels only: edge RMSE 0.5, interior 0, all 0.5 sqrt(9/49).
    std::vector<float> a(std::size_t(w * h), 0.25f), b(a);
    for (std::size_t i = 0; i < a.size(); ++i)
        if (m.edge[i]) b[i] = 0.75f;
    const auto r = split(m, [&](const std::uint8_t* mask) { return rmse(a.data(), b.data(), a.size(), mask); });
    EXPECT_DOUBLE_EQ(r.edge.value, 0.5);
    EXPECT_EQ(r.edge.count, 9u);
    EXPECT_EQ(r.interior.value, 0.0);
    EXPECT_EQ(r.interior.count, 40u);
    EXPECT_DOUBLE_EQ(r.all.value, 0.5 * std::sqrt(9.0 / 49.0));
    const auto bi = split(m, [&](const std::uint8_t* mask) { return bias(b.data(), a.data(), a.size(), mask); });
    EXPECT_DOUBLE_EQ(bi.edge.value, 0.5);
    EXPECT_EQ(bi.interior.value, 0.0);
}
