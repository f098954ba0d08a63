// Rays must not slip through a closed mesh between triangles that share an
// edge: a "crack" pixel, farther than all eight neighbours, would show as a
// speck of the far side (outlined by IBS in every picture). Embree's robust
// mode makes the ray-triangle test watertight.
#include "render_helpers.h"

#include <darkroom/scene/generators.h>
#include <darkroom/scene/scene_file.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;

TEST(CaptureWatertight, NoRaySlipsBetweenTheTrianglesOfAClosedSurface) {
    const auto scene = test::sceneOf(generate("isosurface", {{"resolution", "96"}}));
    Camera proto;
    proto.width = proto.height = 768;
    proto.fovYDegrees = 30;
    int cracks = 0, surface = 0;
    for (double phi : {0.0, 45.0, 90.0, 135.0, 180.0, 225.0, 270.0, 315.0})
        for (double theta : {15.0, 40.0}) {
            const Camera cam = orbitCamera(proto, {0, 0, 0}, 4.6, phi, theta, {0, 0, 1});
            const BufferPtr g = test::capture(scene, cam, CaptureRequest{}, 2);
            const float* z = g->hostFloat("Z");
            for (int y = 1; y < 767; ++y)
                for (int x = 1; x < 767; ++x) {
                    const float c = z[std::size_t(y) * 768 + x];
                    if (!std::isfinite(c)) continue;
                    ++surface;
                    bool behindAll = true;
                    for (int dy = -1; dy <= 1; ++dy)
                        for (int dx = -1; dx <= 1; ++dx)
                            if (dx || dy) {
                                const float n = z[std::size_t(y + dy) * 768 + x + dx];
                                behindAll = behindAll && std::isfinite(n) && c > 1.02f * n;
                            }
                    cracks += behindAll;
                }
        }
    EXPECT_GT(surface, 500000);
    EXPECT_EQ(cracks, 0);
}
