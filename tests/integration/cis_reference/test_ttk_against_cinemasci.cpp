// The TTK database (../shared/data/cinema/ttk_extracts_001.cdb) read, colour
// mapped and composited by our pipeline, compared with the pictures that
// ANOTHER program drew of it: cinemasci's CIS renderer
// (../shared/data/reference/, see the README there). Shapes, positions and
// orientation are compared tightly (silhouette overlap >= 0.98; the transposed
// picture must fail that test), colours loosely, because that renderer
// interpolates the JSON maps linearly in sRGB values and writes them without
// conversion while we interpolate as ParaView does and encode linear colour.
#include "test_support.h"

#include <darkroom/core/evaluator.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/srgb.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

using namespace darkroom;

namespace {

std::string pipeline(const std::string& db) {
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
edges:
  - object0.image -> colour0.image
  - object12.image -> colour12.image
  - colour0.image -> composite.images
  - colour12.image -> composite.images
  - object0.image -> compositeData.images
  - object12.image -> compositeData.images
  - composite.image -> shade.image
  - compositeData.image -> shade.other
)";
}

struct Comparison {
    double overlap = 0;            // |ours ∩ theirs| / |ours ∪ theirs|
    double transposedOverlap = 0;  // the same with our picture mirrored about its diagonal
    double meanColourError = 0;    // mean |sRGB difference| over R, G, B where both cover
    std::size_t covered = 0;       // pixels where both cover
};

// Their background is 0.5 grey written as 128/255; any other pixel is the object.
std::vector<bool> referenceSilhouette(const Buffer& ref) {
    const float* c[3] = {ref.requireFloat("R"), ref.requireFloat("G"), ref.requireFloat("B")};
    std::vector<bool> s(ref.pixelCount());
    for (std::size_t i = 0; i < s.size(); ++i) {
        bool grey = true;
        for (int k = 0; k < 3; ++k) grey &= std::abs(linearToSrgb(c[k][i]) * 255.f - 128.f) < 1.5f;
        s[i] = !grey;
    }
    return s;
}

Comparison compare(const Buffer& ours, const Buffer& ref) {
    Comparison r;
    const int n = ours.width();
    EXPECT_EQ(ours.width(), ref.width());
    EXPECT_EQ(ours.height(), ref.height());
    EXPECT_EQ(ours.width(), ours.height()) << "the transposition check assumes a square picture";
    const float* z = ours.requireFloat("Z");
    const auto theirs = referenceSilhouette(ref);
    const float* a[3] = {ours.requireFloat("R"), ours.requireFloat("G"), ours.requireFloat("B")};
    const float* b[3] = {ref.requireFloat("R"), ref.requireFloat("G"), ref.requireFloat("B")};
    std::size_t both = 0, either = 0, bothT = 0, eitherT = 0;
    double error = 0;
    for (int y = 0; y < n; ++y)
        for (int x = 0; x < n; ++x) {
            const std::size_t i = std::size_t(y) * n + x, t = std::size_t(x) * n + y;
            const bool mine = std::isfinite(z[i]), mineT = std::isfinite(z[t]);
            both += mine && theirs[i];
            either += mine || theirs[i];
            bothT += mineT && theirs[i];
            eitherT += mineT || theirs[i];
            if (mine && theirs[i])
                for (int k = 0; k < 3; ++k) error += std::abs(linearToSrgb(a[k][i]) - linearToSrgb(b[k][i]));
        }
    r.covered = both;
    r.overlap = either ? double(both) / double(either) : 0;
    r.transposedOverlap = eitherT ? double(bothT) / double(eitherT) : 0;
    r.meanColourError = both ? error / (3.0 * double(both)) : 1;
    return r;
}

class TtkAgainstCinemasci : public ::testing::Test {
protected:
    void SetUp() override {
        db_ = test::sharedData("cinema/ttk_extracts_001.cdb");
        refDir_ = test::sharedData("reference");
        if (db_.empty() || refDir_.empty())
            GTEST_SKIP() << "../shared/data/cinema/ttk_extracts_001.cdb or ../shared/data/reference is absent";
        Diagnostics d;
        graph_ = std::make_unique<Graph>(parsePipeline(pipeline(db_), "ttk.yaml", test::pluginRegistry(), d));
        ASSERT_FALSE(hasErrors(d)) << d[0].str();
    }

    BufferPtr reference(const std::string& name) const {
        return readImage(refDir_ + "/cinemasci-ttk_extracts_001-" + name + ".png");
    }

    std::string db_, refDir_;
    std::unique_ptr<Graph> graph_;
    Evaluator ev_;
};

}  // namespace

TEST_F(TtkAgainstCinemasci, StoneAloneStandsUpAsCinemasciDrawsIt) {
    const BufferPtr ours = ev_.evaluateImage(*graph_, "colour0", "image");
    const Comparison c = compare(*ours, *reference("object000"));
    EXPECT_GE(c.overlap, 0.98);
    EXPECT_LT(c.transposedOverlap, 0.8) << "the check must tell the transposed picture apart";
    EXPECT_GT(c.covered, 100000u);
    EXPECT_LT(c.meanColourError, 0.08);  // measured 0.059: Diverging interpolation against linear in sRGB
}

TEST_F(TtkAgainstCinemasci, CompositedByDepthMatches) {
    const BufferPtr ours = ev_.evaluateImage(*graph_, "composite", "image");
    const Comparison c = compare(*ours, *reference("composited"));
    EXPECT_GE(c.overlap, 0.98);
    EXPECT_LT(c.transposedOverlap, 0.8);
    EXPECT_LT(c.meanColourError, 0.08);  // measured 0.054
}

TEST_F(TtkAgainstCinemasci, CompositedAndShadedByTheStoredShadowMatches) {
    const BufferPtr ours = ev_.evaluateImage(*graph_, "shade", "image");
    const BufferPtr theirs = reference("composited-sssao");
    const Comparison c = compare(*ours, *theirs);
    EXPECT_GE(c.overlap, 0.98);
    EXPECT_LT(c.transposedOverlap, 0.8);
    // The shadow darkens the same pixels by the same factor: cinemasci multiplies
    // the encoded 8-bit values by SSSAO, we multiply linear light, so compare
    // each picture's shaded / unshaded ratio (of its brightest channel) instead
    // of the colours, which differ by design (measured mean error 0.13).
    const BufferPtr oursPlain = ev_.evaluateImage(*graph_, "composite", "image");
    const BufferPtr theirsPlain = reference("composited");
    const float* z = ours->requireFloat("Z");
    double error = 0;
    std::size_t n = 0, shaded = 0;
    for (std::size_t i = 0; i < ours->pixelCount(); ++i) {
        if (!std::isfinite(z[i])) continue;
        int k = 0;
        float best = -1;
        for (int ch = 0; ch < 3; ++ch) {
            const float v = linearToSrgb(theirsPlain->requireFloat(std::string(1, "RGB"[ch]))[i]);
            if (v > best) best = v, k = ch;
        }
        if (best < 0.25f) continue;  // 8-bit quantisation dominates dark pixels
        const std::string name(1, "RGB"[k]);
        const float theirRatio = linearToSrgb(theirs->requireFloat(name)[i]) / best;
        const float ourRatio = ours->requireFloat(name)[i] / oursPlain->requireFloat(name)[i];
        error += std::abs(theirRatio - ourRatio);
        shaded += ourRatio < 0.9f;
        ++n;
    }
    ASSERT_GT(n, 100000u);
    EXPECT_GT(shaded, n / 20) << "the shadow channel darkens a visible part of the picture";
    EXPECT_LT(error / double(n), 0.01) << "mean |their ratio - our ratio| (measured 0.0016)";
}

// docs/examples/ttk/ttk-ssao.yaml: our SSAO on the TTK database through the Camera
// node. No reference picture exists, so the test checks what must hold: AO
// within [0, 1], none on the background, darkening in the creases of the
// stone while most of it stays lit.
TEST(TtkSsaoExample, OurSsaoShadesTheTtkDatabaseThroughTheCameraNode) {
    if (test::sharedData("cinema/ttk_extracts_001.cdb").empty())
        GTEST_SKIP() << "../shared/data/cinema/ttk_extracts_001.cdb is absent";
    Diagnostics d;
    const std::string examples = std::string(DARKROOM_SOURCE_DIR) + "/docs/examples/ttk";
    const Graph g = loadPipeline(examples + "/ttk-ssao.yaml", test::pluginRegistry(), d);
    ASSERT_FALSE(hasErrors(d)) << d[0].str();
    EvaluatorOptions options;
    options.inputBase = examples;  // as `darkroom run` resolves the pipeline's relative paths
    Evaluator ev(options);
    const BufferPtr ao = ev.evaluateImage(g, "ao", "image");
    ASSERT_TRUE(ao->metadata().camera);
    const float* a = ao->requireFloat("AO");
    const float* z = ao->requireFloat("Z");
    std::size_t surface = 0, dark = 0, lit = 0;
    for (std::size_t i = 0; i < ao->pixelCount(); ++i) {
        ASSERT_TRUE(a[i] >= 0.f && a[i] <= 1.f) << i;
        if (!std::isfinite(z[i])) {
            EXPECT_EQ(a[i], 1.f) << i;
            continue;
        }
        ++surface;
        dark += a[i] < 0.7f;
        lit += a[i] > 0.9f;
    }
    EXPECT_GT(surface, 150000u);
    EXPECT_GT(dark, surface / 100) << "creases and contacts are darkened";
    EXPECT_GT(lit, surface / 2) << "open surface stays lit";
}
