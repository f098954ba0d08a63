// SSAO on a layered G-buffer (issue 30): it needs one surface, so it reads
// the front layer (the plain channel names) and ignores the deeper layers.
#include "analytic_scenes.h"

#include <darkroom/core/run_filter.h>
#include <darkroom/layers.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace darkroom;
using namespace ssao_test;

TEST(SsaoLayers, ALayeredBufferGivesTheFrontLayersAO) {
    // A sphere in front of a wall: the front layer; behind it a second layer
    // that would occlude very differently (a wall close behind every surface).
    const Camera cam = lookAt({0, 0, 6}, {0, 0, 0}, 96, 96, 30);
    const BufferPtr front = depthImage(cam, [](const Vec3& o, const Vec3& d) {
        return std::min(sphereHit(o, d, {0, 0, 0.4}, 0.3), planeHit(o, d, {0, 0, 0}, {0, 0, 1}));
    });
    auto layered = makeCpuBuffer(front->width(), front->height(), {{"layer1.Z"}});
    for (const auto& c : front->channels()) layered->setPlane(c, front->plane(c.name));
    layered->metadata() = front->metadata();
    float* z1 = layered->writeFloat("layer1.Z");
    for (std::size_t i = 0; i < front->pixelCount(); ++i)
        z1[i] = front->hostFloat("Z")[i] + 0.05f * float(i % 7);
    ASSERT_EQ(layers::count(*layered), 2);

    for (const char* method : {"hemisphere", "horizon"}) {
        auto run = [&](const BufferPtr& image) {
            auto f = test::pluginRegistry().createFilter("SSAO");
            FilterRunOptions o;
            o.threads = 2;
            return runFilter(*f,
                             {{"image", {Value(image)}},
                              {"method", {Value(method)}},
                              {"radiusUnits", {Value("world")}},
                              {"radius", {Value(0.5)}},
                              {"thickness", {Value(0.2)}}},
                             o)
                .outputs.at("image")
                .asImage();
        };
        const BufferPtr a = run(layered), b = run(front);
        float lowest = 1;
        for (std::size_t i = 0; i < a->pixelCount(); ++i) {
            ASSERT_EQ(a->hostFloat("AO")[i], b->hostFloat("AO")[i]) << method << " pixel " << i;
            lowest = std::min(lowest, a->hostFloat("AO")[i]);
        }
        EXPECT_LT(lowest, 0.99f) << method << ": the sphere occludes the wall, so the test compares something";
        EXPECT_TRUE(a->hasChannel("layer1.Z")) << "the deeper layers pass through";
    }
}
