// Compositing of translucent and layered colour inputs (issue 30), with
// known answers: the analytic front-to-back blend, whatever the input order.
#include "test_support.h"

#include <darkroom/core/run_filter.h>
#include <darkroom/layers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

using namespace darkroom;

namespace {

const float kInf = std::numeric_limits<float>::infinity();

BufferPtr compositeImage(const std::vector<BufferPtr>& images) {
    auto f = test::pluginRegistry().createFilter("Compositing");
    std::vector<Value> v;
    for (const auto& b : images) v.emplace_back(b);
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, {{"images", v}}, o).outputs.at("image").asImage();
}

// A surface: depth, straight colour, alpha.
struct Sheet {
    float z, r, g, b, a;
};
// Two translucent planes and an opaque background plane behind them.
const Sheet kRed{2.0f, 0.9f, 0.1f, 0.2f, 0.4f};
const Sheet kBlue{5.0f, 0.1f, 0.3f, 0.8f, 0.7f};
const Sheet kFloor{9.0f, 0.5f, 0.6f, 0.1f, 1.0f};

// alpha1 c1 + (1 - alpha1) alpha2 c2 + (1 - alpha1)(1 - alpha2) c_bg, per channel.
float analytic(float c1, float c2, float cbg) {
    return kRed.a * c1 + (1 - kRed.a) * kBlue.a * c2 + (1 - kRed.a) * (1 - kBlue.a) * cbg;
}

// A 3x1 image of `layers` planes (front first, as layers.h orders them);
// pixel 1 lacks the deeper layers (+inf depth), pixel 2 is background.
std::shared_ptr<WritableBuffer> layered(const std::vector<Sheet>& planes, const std::string& extra = "") {
    std::vector<std::string> names;
    for (std::size_t k = 0; k < planes.size(); ++k)
        for (const char* c : {"R", "G", "B", "A", "Z"}) names.push_back(layers::channel(c, int(k)));
    if (!extra.empty()) names.push_back(extra);
    return test::makeImage(3, 1, names, [&](int x, int, int c) {
        if (std::size_t(c) >= 5 * planes.size()) return 42.0f;  // the extra channel
        const Sheet& p = planes[std::size_t(c) / 5];
        const bool missing = x == 2 || (x == 1 && c >= 5);
        const float v[5] = {p.r, p.g, p.b, p.a, p.z};
        if (missing) return c % 5 == 4 ? kInf : 0.0f;
        return v[c % 5];
    });
}

void expectAnalytic(const Buffer& out, const std::string& what) {
    const float want[3] = {analytic(kRed.r, kBlue.r, kFloor.r), analytic(kRed.g, kBlue.g, kFloor.g),
                           analytic(kRed.b, kBlue.b, kFloor.b)};
    const char* names[3] = {"R", "G", "B"};
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(out.hostFloat(names[c])[0], want[c], 1e-6f) << what << " " << names[c];
    EXPECT_NEAR(out.hostFloat("A")[0], 1.0f, 1e-6f) << what;
    EXPECT_EQ(out.hostFloat("Z")[0], kRed.z) << what;  // the nearest surface's depth
}

}  // namespace

TEST(CompositingLayers, TwoTranslucentPlanesOverABackgroundInEveryInputOrder) {
    std::vector<BufferPtr> in = {layered({kRed}), layered({kBlue}), layered({kFloor})};
    std::vector<int> order = {0, 1, 2};
    int tried = 0;
    do {
        std::vector<BufferPtr> permuted;
        for (int k : order) permuted.push_back(in[std::size_t(k)]);
        expectAnalytic(*compositeImage(permuted),
                       "order " + std::to_string(order[0]) + std::to_string(order[1]) + std::to_string(order[2]));
        ++tried;
    } while (std::next_permutation(order.begin(), order.end()));
    EXPECT_EQ(tried, 6);
}

TEST(CompositingLayers, LayeredInputsFromSeveralDatabasesMergeByDepthInEveryOrder) {
    // Database 1 holds the red plane and the floor, database 2 the blue plane
    // between them: the blend must interleave their layers by depth.
    const BufferPtr a = layered({kRed, kFloor}), b = layered({kBlue});
    expectAnalytic(*compositeImage({a, b}), "a, b");
    expectAnalytic(*compositeImage({b, a}), "b, a");
    // One layered buffer alone is flattened, not forwarded.
    const BufferPtr one = compositeImage({layered({kRed, kBlue, kFloor}, "height")});
    expectAnalytic(*one, "one layered input");
    EXPECT_EQ(one->channelNames(), (std::vector<std::string>{"R", "G", "B", "A", "Z", "height"}));
}

TEST(CompositingLayers, APixelWithFewerLayersBlendsOnlyWhatExists) {
    const BufferPtr out = compositeImage({layered({kRed, kBlue}), layered({kFloor})});
    // Pixel 1: only the red plane exists in the first input (+inf deeper), the
    // floor in the second: red over floor.
    const float want = kRed.a * kRed.g + (1 - kRed.a) * kFloor.g;
    EXPECT_NEAR(out->hostFloat("G")[1], want, 1e-6f);
    EXPECT_NEAR(out->hostFloat("A")[1], 1.0f, 1e-6f);
    // Pixel 2: background everywhere: transparent black at +inf.
    EXPECT_EQ(out->hostFloat("A")[2], 0.0f);
    EXPECT_EQ(out->hostFloat("Z")[2], kInf);
    // Without the floor: red over blue alone stays translucent, straight alpha.
    const BufferPtr two = compositeImage({layered({kRed, kBlue})});
    const float alpha = 1 - (1 - kRed.a) * (1 - kBlue.a);
    EXPECT_NEAR(two->hostFloat("A")[0], alpha, 1e-6f);
    EXPECT_NEAR(two->hostFloat("R")[0], (kRed.a * kRed.r + (1 - kRed.a) * kBlue.a * kBlue.r) / alpha, 1e-6f);
    // Pixel 1 of `two` has the red plane only: its colour bit for bit.
    EXPECT_EQ(two->hostFloat("R")[1], kRed.r);
    EXPECT_EQ(two->hostFloat("A")[1], kRed.a);
}

TEST(CompositingLayers, OpaqueFrontSurfacesAreAZBufferMergeBitForBit) {
    // An opaque plane in front hides a translucent one behind, whatever the order.
    Sheet opaque = kRed;
    opaque.a = 1.0f;
    for (bool swap : {false, true}) {
        std::vector<BufferPtr> in = {layered({opaque}), layered({kBlue})};
        if (swap) std::swap(in[0], in[1]);
        const BufferPtr out = compositeImage(in);
        EXPECT_EQ(out->hostFloat("R")[0], opaque.r);
        EXPECT_EQ(out->hostFloat("G")[0], opaque.g);
        EXPECT_EQ(out->hostFloat("B")[0], opaque.b);
        EXPECT_EQ(out->hostFloat("A")[0], 1.0f);
    }
}
