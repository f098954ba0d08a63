// The box cascade that replaces SSDD's Gaussian: its variance is sigma^2
// exactly, it stays close to the Gaussian, and SSDD computes exactly this
// kernel as a normalised convolution (compared with a direct convolution).
#include "../../normals/tests/depth_scenes.h"
#include "../../normals/tests/simd_targets.h"
#include "../src/box_cascade.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

using namespace darkroom;
using namespace darkroom::test;
using darkroom::passes::boxCascade;
using darkroom::passes::cascadeWeights;

namespace {

struct Moments {
    double sum = 0, mean = 0, variance = 0;
};

Moments moments(const std::vector<double>& k) {
    Moments m;
    const double c = double(k.size() / 2);
    for (std::size_t i = 0; i < k.size(); ++i) m.sum += k[i];
    for (std::size_t i = 0; i < k.size(); ++i) m.mean += k[i] * (double(i) - c) / m.sum;
    for (std::size_t i = 0; i < k.size(); ++i) m.variance += k[i] * (double(i) - c - m.mean) * (double(i) - c - m.mean) / m.sum;
    return m;
}

TEST(BoxCascade, HasTheVarianceOfTheGaussianAndReachesAboutThreeSigma) {
    for (const double sigma : {0.1, 0.3, 1.0, 2.5, 3.0, 10.24, 20.48, 40.96, 100.0}) {
        const auto c = boxCascade(sigma, 100000);
        const std::vector<double> k = cascadeWeights(c);
        const Moments m = moments(k);
        EXPECT_NEAR(m.mean, 0.0, 1e-12) << sigma;
        EXPECT_NEAR(m.variance, sigma * sigma, 1e-9 * (1 + sigma * sigma)) << sigma;
        const int reach = int(k.size() / 2);
        EXPECT_LE(reach, 3.0 * sigma + 3.0) << sigma;
        EXPECT_GE(reach, 3.0 * sigma - 1.5) << sigma;
        for (const auto& b : c) {
            EXPECT_GE(b.alpha, 0.0);
            EXPECT_LT(b.alpha, 1.0 + 1e-12);
        }
    }
}

// The normalised cascade against the normalised Gaussian of the same sigma:
// the largest difference is at the peak, which is about 6 % lower (a
// quadratic B-spline's 3 / (8 sigma) against 1 / (sqrt(2 pi) sigma)).
TEST(BoxCascade, StaysCloseToTheGaussian) {
    for (const double sigma : {3.0, 10.24, 40.96}) {
        const std::vector<double> k = cascadeWeights(boxCascade(sigma, 100000));
        const double total = std::accumulate(k.begin(), k.end(), 0.0);
        const double c = double(k.size() / 2);
        double gaussTotal = 0;
        for (std::size_t i = 0; i < k.size(); ++i) gaussTotal += std::exp(-0.5 * (double(i) - c) * (double(i) - c) / (sigma * sigma));
        double worst = 0, peak = 0;
        for (std::size_t i = 0; i < k.size(); ++i) {
            const double g = std::exp(-0.5 * (double(i) - c) * (double(i) - c) / (sigma * sigma)) / gaussTotal;
            worst = std::max(worst, std::abs(k[i] / total - g));
            peak = std::max(peak, g);
        }
        EXPECT_LT(worst, 0.065 * peak) << sigma;
    }
}

TEST(BoxCascade, SigmaIsCappedAtTheImageSize) {
    const auto wide = boxCascade(512.0, 12), capped = boxCascade(12.0, 12);
    for (int k = 0; k < passes::kBoxes; ++k) {
        EXPECT_EQ(wide[std::size_t(k)].radius, capped[std::size_t(k)].radius);
        EXPECT_EQ(wide[std::size_t(k)].alpha, capped[std::size_t(k)].alpha);
    }
}

// SSDD's factor from a direct normalised convolution with the cascade's
// weights, in double: what the running sums must give.
std::vector<double> directFactor(const Buffer& img, double sigma, double strength) {
    const int w = img.width(), h = img.height();
    const Camera cam = *img.metadata().camera;
    const float* z = img.hostFloat("Z");
    const std::vector<double> kx = cascadeWeights(boxCascade(sigma, std::max(w, h))), ky = kx;
    const int rx = int(kx.size() / 2), ry = int(ky.size() / 2);
    std::vector<double> out(img.pixelCount(), 1.0);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const float zc = z[std::size_t(y) * w + x];
            if (!std::isfinite(zc)) continue;
            double sum = 0, weight = 0;
            for (int dy = -ry; dy <= ry; ++dy)
                for (int dx = -rx; dx <= rx; ++dx) {
                    const int qx = x + dx, qy = y + dy;
                    if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
                    const float zq = z[std::size_t(qy) * w + qx];
                    if (!std::isfinite(zq)) continue;
                    const double k = kx[std::size_t(dx + rx)] * ky[std::size_t(dy + ry)];
                    sum += k * zq;
                    weight += k;
                }
            const double dd = sum / weight - zc;
            const double s = sigma * cam.pixelSizeAt(1.0) * zc;
            if (dd < 0) out[std::size_t(y) * w + x] = std::exp(-strength * -dd / s);
        }
    return out;
}

TEST(BoxCascade, SsddComputesTheCascadeAsANormalisedConvolution) {
    const Camera cam = viewCamera(83, 57, true);
    const BufferPtr img = depthImage(cam, [](int x, int y) {
        if ((x - 60) * (x - 60) + (y - 15) * (y - 15) < 90) return std::numeric_limits<double>::infinity();
        if ((x * 7 + y * 13) % 97 == 0) return std::numeric_limits<double>::quiet_NaN();
        return (x / 11 + y / 9) % 3 == 0 ? 4.0 + 0.01 * x : 6.0 - 0.02 * y;
    });
    for (const double sigma : {0.7, 2.0, 4.5, 30.0}) {
        const BufferPtr out = runPass("SSDD", img, {{"sigma", {Value(sigma)}}, {"sigmaUnits", {Value("pixels")}},
                                                    {"strength", {Value(2.0)}}});
        const std::vector<double> want = directFactor(*img, sigma, 2.0);
        // The sums pass between the boxes in single precision: ~1e-7 of the
        // depths, which the difference dD (a few hundredths of them here)
        // and the exponential's slope turn into ~1e-5 of the factor.
        for (std::size_t i = 0; i < want.size(); ++i)
            ASSERT_NEAR(out->hostFloat("SSDD")[i], want[i], 2e-5) << "sigma " << sigma << " pixel " << i;
    }
}

// Every SIMD instruction set gives the same bits: each sample's sums run in
// the same order whatever the vector width.
TEST(BoxCascade, SsddDoesNotDependOnTheSimdInstructionSet) {
    for (const bool perspective : {true, false}) {
        const Camera cam = viewCamera(75, 43, perspective);
        const BufferPtr img = depthImage(cam, [](int x, int y) {
            if ((x * 5 + y) % 41 == 0) return std::numeric_limits<double>::infinity();
            return 3.0 + ((x / 9 + y / 7) % 3) + 0.01 * x;
        }, {"R", "G", "B"});
        for (const double sigma : {1.5, 6.0, 200.0}) {
            const Inputs p{{"sigma", {Value(sigma)}}, {"sigmaUnits", {Value("pixels")}}, {"apply", {Value(true)}}};
            const auto results = resultsPerSimdTarget([&] { return runPass("SSDD", img, p); });
            for (const auto& [target, out] : results)
                EXPECT_TRUE(identical(*out, *results.front().second)) << sigma << ": " << target << " differs from "
                                                                      << results.front().first;
        }
    }
}

}  // namespace
