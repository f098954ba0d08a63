// SSAO keeps its frame (depth planes and normals) between executions of one
// instance (frame_cache.h): a second execution with another radius, or on
// another depth, camera or blur radius, gives the bits a fresh instance gives.
#include "analytic_scenes.h"

#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>

#include <gtest/gtest.h>

using namespace darkroom;
using namespace ssao_test;

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

BufferPtr run(Filter& f, const BufferPtr& image, double radius, int blurRadius = 2) {
    Inputs params{{"image", {Value(image)}}, {"radius", {Value(radius)}}, {"blurRadius", {Value(blurRadius)}}};
    FilterRunOptions o;
    o.threads = 2;
    return runFilter(f, params, o).outputs.at("image").asImage();
}

BufferPtr fresh(const BufferPtr& image, double radius, int blurRadius = 2) {
    auto f = test::pluginRegistry().createFilter("SSAO");
    return run(*f, image, radius, blurRadius);
}

}  // namespace

TEST(SsaoFrameCache, ASecondExecutionEqualsAFreshInstance) {
    const Camera cam = lookAt({3.2, 2.6, 3.5}, {0.6, 0.2, 0}, 90, 70, 50);
    const Camera other = lookAt({2.5, 3.0, 3.8}, {0.4, 0.1, 0}, 90, 70, 50);
    const BufferPtr z = depthImage(cam, cornerHit);
    const BufferPtr z2 = depthImage(other, cornerHit);
    auto f = test::pluginRegistry().createFilter("SSAO");
    EXPECT_TRUE(identical(*run(*f, z, 0.05), *fresh(z, 0.05)));
    EXPECT_TRUE(identical(*run(*f, z, 0.12), *fresh(z, 0.12)));        // same frame, other radius
    EXPECT_TRUE(identical(*run(*f, z2, 0.12), *fresh(z2, 0.12)));      // other depth and camera
    EXPECT_TRUE(identical(*run(*f, z2, 0.12, 5), *fresh(z2, 0.12, 5)));  // other padding
    EXPECT_TRUE(identical(*run(*f, z, 0.05), *fresh(z, 0.05)));        // back to the first
}
