// ColorMapping on layered G-buffers (issue 30, layers.h naming), with known
// answers: each layer's colour is what ColorMapping gives that layer alone
// (same range), and the blend is the analytic front-to-back one.
#include "test_support.h"

#include <darkroom/core/run_filter.h>
#include <darkroom/error.h>
#include <darkroom/layers.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;
const float kInf = std::numeric_limits<float>::infinity();
const float kNaN = std::numeric_limits<float>::quiet_NaN();

FilterRunResult mapImage(const BufferPtr& image, Inputs extra = {}) {
    auto f = test::pluginRegistry().createFilter("ColorMapping");
    extra["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(*f, extra, o);
}
BufferPtr mapped(const BufferPtr& image, Inputs extra = {}) {
    return mapImage(image, std::move(extra)).outputs.at("image").asImage();
}

// A layer of a 4x1 G-buffer: depth, the scalar `value` and the object id.
struct Layer {
    float z, value;
    std::uint32_t object;
};
// Pixel x holds the layers whose index is below layersAt[x]; the others are
// missing (+inf depth, NaN value, id 0xffffffff), as layers.h says.
std::shared_ptr<WritableBuffer> gbuffer(const std::vector<Layer>& layers, const std::vector<int>& layersAt) {
    std::vector<ChannelDesc> channels;
    for (std::size_t k = 0; k < layers.size(); ++k) {
        channels.emplace_back(layers::channel("Z", int(k)));
        channels.emplace_back(layers::channel("value", int(k)));
        channels.emplace_back(layers::channel("objectId", int(k)), ChannelType::UInt32);
    }
    auto b = makeCpuBuffer(int(layersAt.size()), 1, channels);
    for (std::size_t k = 0; k < layers.size(); ++k)
        for (std::size_t x = 0; x < layersAt.size(); ++x) {
            const bool here = int(k) < layersAt[x];
            b->writeFloat(layers::channel("Z", int(k)))[x] = here ? layers[k].z : kInf;
            b->writeFloat(layers::channel("value", int(k)))[x] = here ? layers[k].value : kNaN;
            b->writeUInt(layers::channel("objectId", int(k)))[x] = here ? layers[k].object : 0xFFFFFFFFu;
        }
    return b;
}

// Two translucent planes (objects 0 and 1) over an opaque floor (object 2).
const std::vector<Layer> kPlanes = {{2.0f, 0.0f, 0}, {5.0f, 1.0f, 1}, {9.0f, 2.0f, 2}};
const Inputs kManual = {{"range", {Value("manual")}}, {"minimum", {Value(0.0)}}, {"maximum", {Value(2.0)}}};

Inputs with(Inputs a, const Inputs& b) {
    for (const auto& [k, v] : b) a[k] = v;
    return a;
}

// The colour ColorMapping gives value v alone (manual range 0..2).
Color alone(float v) {
    const BufferPtr one = mapped(gbuffer({{1.0f, v, 0}}, {1}), kManual);
    return {one->hostFloat("R")[0], one->hostFloat("G")[0], one->hostFloat("B")[0], one->hostFloat("A")[0]};
}

void expectBlend(const Buffer& out, std::size_t i, const std::vector<float>& alpha, const std::vector<Color>& c,
                 const std::string& what) {
    float transmit = 1, r = 0, g = 0, b = 0;
    for (std::size_t k = 0; k < alpha.size(); ++k) {
        r += alpha[k] * transmit * c[k].r, g += alpha[k] * transmit * c[k].g, b += alpha[k] * transmit * c[k].b;
        transmit *= 1 - alpha[k];
    }
    const float a = 1 - transmit;
    EXPECT_NEAR(out.hostFloat("A")[i], a, 1e-6f) << what;
    EXPECT_NEAR(out.hostFloat("R")[i] * a, r, 1e-6f) << what;
    EXPECT_NEAR(out.hostFloat("G")[i] * a, g, 1e-6f) << what;
    EXPECT_NEAR(out.hostFloat("B")[i] * a, b, 1e-6f) << what;
}

}  // namespace

TEST(ColorMappingLayers, PerObjectOpacityBlendsTwoTranslucentPlanesOverTheFloor) {
    const BufferPtr in = gbuffer(kPlanes, {3, 1, 0, 2});
    const BufferPtr out = mapped(in, with(kManual, {{"objectOpacity", {Value("0: 0.4, 1: 0.7")}}}));
    EXPECT_EQ(out->channelNames(), (std::vector<std::string>{"R", "G", "B", "A", "Z"}));
    const std::vector<Color> c = {alone(0.0f), alone(1.0f), alone(2.0f)};
    // alpha1 c1 + (1 - alpha1) alpha2 c2 + (1 - alpha1)(1 - alpha2) c_floor; the floor is opaque.
    expectBlend(*out, 0, {0.4f, 0.7f, 1.0f}, c, "three layers");
    EXPECT_NEAR(out->hostFloat("A")[0], 1.0f, 1e-6f);
    EXPECT_EQ(out->hostFloat("Z")[0], 2.0f);  // the nearest surface that shows
    // Pixel 1 has the front plane only: its colour, bit for bit, at its alpha.
    EXPECT_EQ(out->hostFloat("R")[1], c[0].r);
    EXPECT_EQ(out->hostFloat("A")[1], 0.4f);
    // Pixel 2 is background: transparent black at +inf.
    EXPECT_EQ(out->hostFloat("A")[2], 0.0f);
    EXPECT_EQ(out->hostFloat("Z")[2], kInf);
    expectBlend(*out, 3, {0.4f, 0.7f}, c, "two layers");
}

TEST(ColorMappingLayers, TheOpacityPortAndAHiddenObject) {
    const BufferPtr in = gbuffer(kPlanes, {3});
    const std::vector<Color> c = {alone(0.0f), alone(1.0f), alone(2.0f)};
    expectBlend(*mapped(in, with(kManual, {{"opacity", {Value(0.5)}}})), 0, {0.5f, 0.5f, 0.5f}, c, "opacity 0.5");
    // Opacities multiply; object 0 at 0 is gone, and so is its depth.
    const BufferPtr hidden = mapped(in, with(kManual, {{"opacity", {Value(0.5)}}, {"objectOpacity", {Value("0: 0")}}}));
    expectBlend(*hidden, 0, {0.5f, 0.5f}, {c[1], c[2]}, "object 0 hidden");
    EXPECT_EQ(hidden->hostFloat("Z")[0], 5.0f);
}

TEST(ColorMappingLayers, OpaqueLayersGiveTheFrontLayersImageBitForBit) {
    // Automatic range: only the front layer can be seen, so only its values count.
    const BufferPtr layered = gbuffer(kPlanes, {3, 2, 1, 0});
    auto front = makeCpuBuffer(4, 1, {{"Z"}, {"value"}, {"objectId", ChannelType::UInt32}});
    for (const char* name : {"Z", "value"}) front->setPlane({name}, layered->plane(name));
    front->setPlane({"objectId", ChannelType::UInt32}, layered->plane("objectId"));
    const auto a = mapImage(layered), b = mapImage(front);
    EXPECT_TRUE(identical(*a.outputs.at("image").asImage(), *b.outputs.at("image").asImage()));
    EXPECT_EQ(a.outputs.at("usedMaximum").asFloat(), b.outputs.at("usedMaximum").asFloat());
    // Translucent: the range spans every layer that shows.
    const auto t = mapImage(layered, {{"opacity", {Value(0.5)}}});
    EXPECT_EQ(t.outputs.at("usedMinimum").asFloat(), 0.0);
    EXPECT_EQ(t.outputs.at("usedMaximum").asFloat(), 2.0);
}

TEST(ColorMappingLayers, KeepOutputsEveryLayersColour) {
    const BufferPtr in = gbuffer(kPlanes, {3, 1});
    const BufferPtr out = mapped(in, with(kManual, {{"layers", {Value("keep")}}, {"objectOpacity", {Value("1: 0.7")}}}));
    EXPECT_EQ(layers::count(*out), 3);
    for (int k = 0; k < 3; ++k) {
        const Color want = alone(kPlanes[std::size_t(k)].value);
        EXPECT_EQ(out->hostFloat(layers::channel("R", k))[0], want.r) << k;
        EXPECT_EQ(out->hostFloat(layers::channel("A", k))[0], k == 1 ? 0.7f : 1.0f) << k;
        EXPECT_EQ(out->hostFloat(layers::channel("Z", k))[0], kPlanes[std::size_t(k)].z) << k;
    }
    // A missing layer is transparent background.
    EXPECT_EQ(out->hostFloat("layer1.A")[1], 0.0f);
    EXPECT_EQ(out->hostFloat("layer1.Z")[1], kInf);
}

TEST(ColorMappingLayers, ObjectOpacityTextErrors) {
    const BufferPtr in = gbuffer(kPlanes, {3});
    auto errorOf = [&](const std::string& text) {
        try {
            mapped(in, {{"objectOpacity", {Value(text)}}});
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(errorOf("0 0.3"), HasSubstr("is not 'id: opacity'"));
    EXPECT_THAT(errorOf("0: 1.5"), HasSubstr("must lie in [0, 1]"));
    EXPECT_THAT(errorOf("1: 0.5, 1: 0.2"), HasSubstr("listed twice"));
    EXPECT_EQ(errorOf(" 0: 0.3 ; 2: 1 "), "no error");
    auto noIds = test::makeImage(2, 1, {"Z", "value"}, [](int, int, int) { return 1.0f; });
    try {
        mapped(noIds, {{"objectOpacity", {Value("0: 0.5")}}});
        ADD_FAILURE() << "no error without objectId";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("objectId"));
    }
}
