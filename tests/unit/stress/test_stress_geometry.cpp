// Every stress family builds and its scene is valid: indices in range, field
// sizes right, finite vertices, the colour field on every object inside
// [fieldMin, fieldMax], deterministic, and the camera sees the geometry.
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include "stress_test_util.h"

#include <cctype>
#include <cmath>
#include <map>
#include <set>

using namespace darkroom;
using darkroom::stress::StressScene;
using namespace darkroom::stress_test;

namespace {

stress::Options small() {
    stress::Options o;
    o.width = 64;
    o.height = 64;
    return o;
}

std::size_t cellCount(const SceneObject& o) {
    if (o.primitiveCell.empty()) return o.primitiveCount();
    std::size_t n = 0;
    for (auto c : o.primitiveCell) n = std::max<std::size_t>(n, std::size_t(c) + 1);
    return n;
}

TEST(StressFamilies, ListedInTheDocumentedOrder) {
    const std::vector<std::string> expected = {"plane",   "corner",    "terrain", "particles", "streamlines", "slabs",
                                               "staircase", "grazing", "border",  "gyroid",    "stripes",
                                               "shells",    "sheets"};
    EXPECT_EQ(stress::families(), expected);
}

class EveryFamily : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryFamily, DefaultSceneIsValid) {
    const std::string family = GetParam();
    const double knob = stress::knobValues(family).front();
    const StressScene s = stress::make(family, knob, small());
    EXPECT_EQ(s.family, family);
    EXPECT_EQ(s.knobValue, knob);
    EXPECT_EQ(s.knob.empty(), knob == 0.0);
    EXPECT_FALSE(s.description.empty());
    EXPECT_EQ(s.camera.width, 64);
    EXPECT_EQ(s.camera.height, 64);
    EXPECT_EQ(s.camera.projection, Camera::Projection::Perspective);
    EXPECT_NEAR(s.camera.fovYDegrees, 40.0, 5.0);
    EXPECT_GT(s.aoRadius, 0.0);
    EXPECT_GT(s.focalDistance, 0.0);
    EXPECT_LT(s.fieldMin, s.fieldMax);
    EXPECT_EQ(s.name.rfind(family, 0), 0u) << s.name;
    for (char ch : s.name)
        EXPECT_TRUE(std::isalnum(static_cast<unsigned char>(ch)) || ch == '-' || ch == '.') << s.name;
    ASSERT_TRUE(s.scene);
    ASSERT_FALSE(s.scene->objects.empty());
    for (const auto& o : s.scene->objects) {
        SCOPED_TRACE(o.name);
        ASSERT_EQ(o.vertices.size() % 4, 0u);
        const std::size_t nv = o.vertexCount();
        ASSERT_GT(nv, 0u);
        for (float v : o.vertices) ASSERT_TRUE(std::isfinite(v));
        switch (o.representation) {
            case Representation::Surface:
                ASSERT_EQ(o.indices.size() % 3, 0u);
                ASSERT_GT(o.indices.size(), 0u);
                for (auto i : o.indices) ASSERT_LT(i, nv);
                break;
            case Representation::Lines:
                ASSERT_GT(o.indices.size(), 0u);
                for (auto i : o.indices) ASSERT_LT(std::size_t(i) + 1, nv);
                for (std::size_t i = 0; i < nv; ++i) ASSERT_GT(radiusOf(o, i), 0.0);
                break;
            case Representation::Points:
                EXPECT_TRUE(o.indices.empty());
                for (std::size_t i = 0; i < nv; ++i) ASSERT_GT(radiusOf(o, i), 0.0);
                break;
        }
        ASSERT_TRUE(o.primitiveCell.empty() || o.primitiveCell.size() == o.primitiveCount());
        const ScalarField* f = o.field(s.colorField);
        ASSERT_NE(f, nullptr) << "object lacks colour field " << s.colorField;
        for (const auto& field : o.fields) {
            if (field.association == ScalarField::Association::Point)
                EXPECT_EQ(field.values.size(), nv) << field.name;
            else
                EXPECT_EQ(field.values.size(), cellCount(o)) << field.name;
        }
        for (float v : f->values) {
            ASSERT_FALSE(std::isnan(v));
            ASSERT_GE(v, s.fieldMin);
            ASSERT_LE(v, s.fieldMax);
        }
    }
}

// Share of the image the geometry covers, by ray casting a 16 x 16 grid.
// Families with a plane or backdrop behind the subject cover all of it;
// grazing shows the sky above the horizon and border an empty background.
TEST_P(EveryFamily, CameraSeesTheGeometry) {
    const std::string family = GetParam();
    const StressScene s = stress::make(family, stress::knobValues(family).front(), small());
    const std::map<std::string, std::pair<double, double>> bounds = {
        {"grazing", {0.6, 0.85}}, {"border", {0.1, 0.7}}, {"gyroid", {0.3, 0.95}},
        {"shells", {0.4, 0.7}},   {"sheets", {0.5, 0.95}}};
    const auto it = bounds.find(family);
    const auto [lo, hi] = it == bounds.end() ? std::pair{0.99, 1.0} : it->second;
    // The gyroid's ~10^5 triangles make brute-force rays slow: fewer of them.
    const double c = coverage(*s.scene, s.camera, family == "gyroid" ? 8 : 16);
    EXPECT_GE(c, lo);
    EXPECT_LE(c, hi);
    if (family != "border") {
        // The subject is where the camera looks, near the focal distance.
        Vec3 o, d;
        s.camera.ray(32, 32, o, d);
        const double t = castRay(*s.scene, o, d);  // planar depth: forward component of d is 1
        ASSERT_LT(t, kMiss);
        EXPECT_GT(t, 0.5 * s.focalDistance);
        EXPECT_LT(t, 2.0 * s.focalDistance);
    }
}

// Planes and backdrops reach past the view for wide and tall images too.
TEST_P(EveryFamily, WideAndTallImagesStayCovered) {
    const std::string family = GetParam();
    if (family == "grazing" || family == "border" || family == "gyroid" || family == "shells" || family == "sheets")
        return;  // background by design
    for (auto [w, h] : {std::pair{96, 40}, std::pair{40, 96}}) {
        stress::Options o;
        o.width = w;
        o.height = h;
        for (double knob : stress::knobValues(family)) {
            const StressScene s = stress::make(family, knob, o);
            EXPECT_EQ(coverage(*s.scene, s.camera, 12), 1.0) << s.name << " at " << w << " x " << h;
        }
    }
}

TEST_P(EveryFamily, IsDeterministic) {
    const std::string family = GetParam();
    for (double knob : stress::knobValues(family)) {
        const StressScene a = stress::make(family, knob, small()), b = stress::make(family, knob, small());
        ASSERT_EQ(a.scene->objects.size(), b.scene->objects.size());
        for (std::size_t i = 0; i < a.scene->objects.size(); ++i) {
            EXPECT_EQ(a.scene->objects[i].vertices, b.scene->objects[i].vertices);
            EXPECT_EQ(a.scene->objects[i].indices, b.scene->objects[i].indices);
        }
        EXPECT_EQ(a.camera, b.camera);
        EXPECT_EQ(a.name, b.name);
    }
}

TEST_P(EveryFamily, SweepMakesEveryListedValueWithDistinctNames) {
    const std::string family = GetParam();
    const auto values = stress::knobValues(family);
    ASSERT_FALSE(values.empty());
    const auto scenes = stress::sweep(family, small());
    ASSERT_EQ(scenes.size(), values.size());
    std::set<std::string> names;
    for (std::size_t i = 0; i < scenes.size(); ++i) {
        EXPECT_EQ(scenes[i].knobValue, values[i]);
        names.insert(scenes[i].name);
    }
    EXPECT_EQ(names.size(), scenes.size());
}

// The analytic AO, where given, is 1 on unoccluded planes and at most 1.
TEST_P(EveryFamily, AnalyticAoIsAVisibility) {
    const StressScene s = stress::make(GetParam(), stress::knobValues(GetParam()).front(), small());
    if (!s.analyticAo) return;  // which families have one: test_stress_analytic_ao.cpp
    for (const auto& o : s.scene->objects)
        for (std::size_t i = 0; i < o.vertexCount(); i += 7) {
            const double ao = s.analyticAo(vertex(o, i), s.aoRadius, reference::AoWeighting::Cosine);
            ASSERT_GE(ao, 0.5);
            ASSERT_LE(ao, 1.0);
        }
}

INSTANTIATE_TEST_SUITE_P(Stress, EveryFamily, ::testing::ValuesIn(stress::families()),
                         [](const auto& info) { return info.param; });

TEST(StressBorder, ObjectsCrossTheLeftAndTopImageEdges) {
    const StressScene s = stress::make("border", 0, small());
    bool left = false, top = false;
    for (const auto& o : s.scene->objects) {
        double minX = 1e300, maxX = -1e300, minY = 1e300, maxY = -1e300;
        for (std::size_t i = 0; i < o.vertexCount(); ++i) {
            double px, py;
            ASSERT_TRUE(project(s.camera, vertex(o, i), px, py));
            minX = std::min(minX, px), maxX = std::max(maxX, px), minY = std::min(minY, py), maxY = std::max(maxY, py);
        }
        left = left || (minX < 0 && maxX > 0);
        top = top || (minY < 0 && maxY > 0);
    }
    EXPECT_TRUE(left);
    EXPECT_TRUE(top);
}

}  // namespace
