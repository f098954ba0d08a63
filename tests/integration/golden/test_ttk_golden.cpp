// Golden test on a database written by TTK (../shared/data/cinema/
// ttk_extracts_001.cdb): the two objects' composable images composited by
// depth, each colour-mapped with its own ParaView JSON colour map, and shaded
// with the screen-space AO channel TTK stored (SSSAO). The expected picture
// (tests/fixtures/golden/ttk_extracts_001.png, 256x256) was inspected by eye
// when it was made; besides matching it, the test checks properties that do
// not depend on it.
#include "test_support.h"

#include <darkroom/framework/evaluator.h>
#include <darkroom/framework/image_io.h>
#include <darkroom/framework/pipeline.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;

namespace {

std::string pipeline(const std::string& db, const std::string& output) {
    return R"(darkroom: 1
nodes:
  object0:
    type: CinemaReader
    parameters:
      database: )" + db + R"(
      parameters: object=000
  object12:
    type: CinemaReader
    parameters:
      database: )" + db + R"(
      parameters: object=012
  colour0:
    type: ColorMapping
    parameters:
      channel: Elevation
      colormap: )" + db + R"(/colormap/cooltowarm.json
  colour12:
    type: ColorMapping
    parameters:
      channel: Elevation
      colormap: )" + db + R"(/colormap/blackbody.json
  composite:
    type: Compositing
  compositeData:
    type: Compositing
  shade:
    type: Mix
    parameters:
      mode: multiply
      factorChannel: SSSAO
  small:
    type: Resize
    parameters:
      width: 256
      height: 256
  write:
    type: ImageWriter
    parameters:
      path: )" + output + R"(
edges:
  - object0.image -> colour0.image
  - object12.image -> colour12.image
  - colour0.image -> composite.images
  - colour12.image -> composite.images
  - composite.image -> shade.image
  - object0.image -> compositeData.images
  - object12.image -> compositeData.images
  - compositeData.image -> shade.other
  - shade.image -> small.image
  - small.image -> write.image
)";
}

}  // namespace

TEST(GoldenTtkExtracts, CompositedColourMappedAndShadedMatchesTheExpectedPicture) {
    const std::string db = test::sharedData("cinema/ttk_extracts_001.cdb");
    if (db.empty()) GTEST_SKIP() << "../shared/data is absent";
    test::TempDir dir;
    Diagnostics d;
    Graph g = parsePipeline(pipeline(db, dir.file("ttk.png")), "golden.yaml", test::pluginRegistry(), d);
    ASSERT_FALSE(hasErrors(d)) << d[0].str();
    Evaluator ev;
    ev.run(g);

    // Independent of the picture: compositing by depth picks the nearer object.
    const BufferPtr data = ev.evaluateImage(g, "compositeData", "image");
    const BufferPtr a = ev.evaluateImage(g, "object0", "image");
    const BufferPtr b = ev.evaluateImage(g, "object12", "image");
    const float* z = data->requireFloat("Z");
    const float* za = a->requireFloat("Z");
    const float* zb = b->requireFloat("Z");
    std::size_t overlap = 0, background = 0;
    for (std::size_t i = 0; i < data->pixelCount(); ++i) {
        EXPECT_EQ(z[i], std::min(za[i], zb[i])) << i;
        overlap += std::isfinite(za[i]) && std::isfinite(zb[i]);
        background += !std::isfinite(z[i]);
    }
    EXPECT_GT(overlap, 1000u) << "the two objects overlap on screen";
    EXPECT_GT(background, data->pixelCount() / 4);

    const auto got = readImage(dir.file("ttk.png"));
    const auto want = readImage(std::string(DARKROOM_SOURCE_DIR) + "/tests/fixtures/golden/ttk_extracts_001.png");
    ASSERT_EQ(got->width(), want->width());
    ASSERT_EQ(got->height(), want->height());
    double sum = 0;
    std::size_t n = 0;
    for (const char* c : {"R", "G", "B", "A"}) {
        const float* p = got->requireFloat(c);
        const float* q = want->requireFloat(c);
        for (std::size_t i = 0; i < got->pixelCount(); ++i, ++n) sum += double(p[i] - q[i]) * (p[i] - q[i]);
    }
    const double rmse = std::sqrt(sum / double(n));
    EXPECT_LT(rmse, 0.01) << "RMSE against the expected picture";
}
