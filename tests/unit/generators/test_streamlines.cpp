#include "mesh_checks.h"

#include <darkroom/error.h>
#include <darkroom/scene/generators.h>
#include <darkroom/limits.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using darkroom::test::vertexAt;

namespace {

SceneObject streamlines(const std::map<std::string, std::string>& params = {}) {
    auto objects = generate("streamlines", params);
    EXPECT_EQ(objects.size(), 1u);
    return objects.at(0);
}

const double kA = std::sqrt(3.0), kB = std::sqrt(2.0), kC = 1.0;

}  // namespace

TEST(Streamlines, DefaultsGiveOneTubePerSeed) {
    const SceneObject o = streamlines();
    EXPECT_EQ(o.representation, Representation::Lines);
    ASSERT_NE(o.field("time"), nullptr);
    ASSERT_NE(o.field("speed"), nullptr);
    ASSERT_NE(o.field("line"), nullptr);
    EXPECT_EQ(o.field("time")->values.size(), o.vertexCount());
    EXPECT_EQ(o.field("line")->association, ScalarField::Association::Cell);
    EXPECT_EQ(o.field("line")->values.size(), 100u);  // ABC flow has no stagnation point at a hashed seed
    EXPECT_EQ(o.primitiveCell.size(), o.indices.size());
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        EXPECT_FLOAT_EQ(o.vertices[i * 4 + 3], 0.006f);
        const Vec3 p = vertexAt(o, i);
        ASSERT_LE(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0 + 1e-6);
    }
}

TEST(Streamlines, SegmentsFollowTheFlow) {
    const SceneObject o = streamlines({{"step", "0.05"}});
    ASSERT_GT(o.indices.size(), 1000u);
    for (std::size_t s = 0; s < o.indices.size(); ++s) {
        const Vec3 a = vertexAt(o, o.indices[s]), b = vertexAt(o, o.indices[s] + 1);
        const Vec3 v = generators::abcVelocity((a + b) * 0.5, kA, kB, kC);
        if (length(b - a) < 1e-5) continue;  // a line clipped right at the cube's face
        ASSERT_GT(dot(normalize(b - a), normalize(v)), 0.995) << "segment " << s;
    }
}

TEST(Streamlines, TimeIncreasesAlongEachLineAndLinesStaySeparate) {
    const SceneObject o = streamlines({{"count", "40"}});
    const auto& time = o.field("time")->values;
    const auto& speed = o.field("speed")->values;
    double maxStep = 0;
    for (std::size_t s = 0; s < o.indices.size(); ++s) {
        const std::uint32_t i = o.indices[s];
        ASSERT_LT(i + 1, o.vertexCount());
        ASSERT_GT(time[i + 1], time[i]) << "segment " << s;
        // A segment covers at most one RK4 step: one joining two lines would be longer.
        const double allowed = 0.05 * 1.05 * std::max(speed[i], speed[i + 1]) + 1e-6;
        maxStep = std::max(maxStep, length(vertexAt(o, i + 1) - vertexAt(o, i)) / allowed);
        ASSERT_LE(length(vertexAt(o, i + 1) - vertexAt(o, i)), allowed) << "segment " << s;
        // Segments of one line are consecutive and share its cell.
        if (s > 0 && o.primitiveCell[s] == o.primitiveCell[s - 1]) {
            ASSERT_EQ(o.indices[s - 1] + 1, i);
        }
    }
    // Between two lines exactly one vertex index is skipped (the last of a line).
    std::size_t lineStarts = 1;
    for (std::size_t s = 1; s < o.indices.size(); ++s)
        if (o.indices[s] != o.indices[s - 1] + 1) {
            ++lineStarts;
            ASSERT_NE(o.primitiveCell[s], o.primitiveCell[s - 1]);
        }
    EXPECT_EQ(lineStarts, 40u);
    EXPECT_EQ(o.vertexCount(), o.indices.size() + 40);
}

TEST(Streamlines, BothDirectionsPutTheSeedAtTimeZero) {
    const SceneObject both = streamlines({{"count", "5"}});
    const SceneObject forward = streamlines({{"count", "5"}, {"direction", "forward"}});
    const auto& tb = both.field("time")->values;
    EXPECT_LT(*std::min_element(tb.begin(), tb.end()), 0.f);
    const auto& tf = forward.field("time")->values;
    EXPECT_EQ(*std::min_element(tf.begin(), tf.end()), 0.f);
    EXPECT_GT(both.vertexCount(), forward.vertexCount());
}

TEST(Streamlines, LengthOrStepsBoundTheIntegrationTime) {
    const SceneObject o = streamlines({{"length", "1"}, {"step", "0.1"}, {"direction", "forward"}});
    const auto& t = o.field("time")->values;
    EXPECT_LE(*std::max_element(t.begin(), t.end()), 1.0f + 1e-5f);
    const SceneObject s = streamlines({{"steps", "3"}, {"direction", "forward"}, {"count", "10"}});
    EXPECT_LE(s.vertexCount(), 10u * 4);
    EXPECT_THROW(streamlines({{"steps", "3"}, {"length", "1"}}), Error);
}

TEST(Streamlines, RadiusIsStoredPerVertex) {
    const SceneObject o = streamlines({{"radius", "0.02"}, {"count", "3"}});
    for (std::size_t i = 0; i < o.vertexCount(); ++i) EXPECT_FLOAT_EQ(o.vertices[i * 4 + 3], 0.02f);
}

// A million lines of a million steps (10^12 RK4 steps, terabytes of
// vertices) ran for hours and until memory ran out; the bound is checked
// before a line is traced, against --max-decoded-bytes (8 GiB by default).
TEST(Streamlines, WorkBeyondTheDecodedBytesLimitIsRefusedBeforeTracing) {
    try {
        streamlines({{"count", "1000000"}, {"steps", "1000000"}});
        FAIL() << "no error";
    } catch (const Error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("generator 'streamlines': parameter 'steps' makes up to 2000001000000 vertices"),
                  std::string::npos)
            << what;
        EXPECT_NE(what.find("--max-decoded-bytes"), std::string::npos) << what;
    }
    // The same under a limit the defaults fit: 100 lines of 200 steps both ways, 24 bytes a vertex.
    const std::uint64_t saved = limit(Limit::DecodedBytes);
    setLimit(Limit::DecodedBytes, 100 * 401 * 24);
    EXPECT_NO_THROW(streamlines());
    setLimit(Limit::DecodedBytes, 100 * 401 * 24 - 1);
    EXPECT_THROW(streamlines(), Error);
    setLimit(Limit::DecodedBytes, saved);
}
