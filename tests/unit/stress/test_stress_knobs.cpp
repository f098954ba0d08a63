// Each knob means what it says, computed back from the geometry and camera:
// projected particle radius and line width in pixels, grazing angle, slab
// gap, step height and stripe period; bad family names and knob values are
// rejected with messages that name the family.
#include <darkroom/error.h>
#include <darkroom/accuracy/stress_scenes.h>

#include <gtest/gtest.h>

#include "stress_test_util.h"

#include <cmath>
#include <set>

using namespace darkroom;
using darkroom::stress::StressScene;
using namespace darkroom::stress_test;

namespace {

constexpr double kPi = 3.14159265358979323846;

stress::Options size(int w, int h) {
    stress::Options o;
    o.width = w;
    o.height = h;
    return o;
}

const SceneObject& objectWith(const StressScene& s, Representation r) {
    for (const auto& o : s.scene->objects)
        if (o.representation == r) return o;
    throw std::runtime_error("no object of that representation in " + s.name);
}

const SceneObject& objectNamed(const StressScene& s, const std::string& name) {
    for (const auto& o : s.scene->objects)
        if (o.name == name) return o;
    throw std::runtime_error("no object '" + name + "' in " + s.name);
}

TEST(StressKnobs, ParticleRadiusIsTheProjectedRadiusAtTheCloudCentre) {
    for (double knob : {0.5, 1.0, 2.0, 4.0, 8.0, 20.0, 0.25, 64.0, 3.3}) {
        const StressScene s = stress::make("particles", knob, size(96, 64));
        const SceneObject& cloud = objectWith(s, Representation::Points);
        const double pixel = s.camera.pixelSizeAt(s.focalDistance);
        Vec3 mean;
        for (std::size_t i = 0; i < cloud.vertexCount(); ++i) {
            EXPECT_NEAR(radiusOf(cloud, i) / pixel, knob, 1e-5 * knob);
            // Every sphere lies near the centre's depth, so its own
            // projected radius is the knob within a few percent.
            const double depth = s.camera.depthOf(vertex(cloud, i));
            EXPECT_NEAR(radiusOf(cloud, i) / s.camera.pixelSizeAt(depth), knob, 0.03 * knob);
            mean = mean + vertex(cloud, i) * (1.0 / double(cloud.vertexCount()));
        }
        // The cloud centre (the focal distance) is on the view axis.
        Vec3 o, d;
        s.camera.ray(48, 32, o, d);
        EXPECT_NEAR(s.camera.depthOf(o + d * s.focalDistance), s.focalDistance, 1e-9);
        if (cloud.vertexCount() >= 100) {
            EXPECT_NEAR(s.camera.depthOf(mean), s.focalDistance, 0.01 * s.focalDistance);
        }
    }
}

TEST(StressKnobs, ParticleCountFallsWithRadiusAndCoverageStaysModerate) {
    std::size_t previous = ~std::size_t(0);
    for (double knob : stress::knobValues("particles")) {
        const StressScene s = stress::make("particles", knob, size(128, 128));
        const SceneObject& cloud = objectWith(s, Representation::Points);
        EXPECT_LE(cloud.vertexCount(), previous);
        previous = cloud.vertexCount();
        if (knob > 4) continue;  // a handful of big spheres covers what it covers
        Scene only;
        only.objects.push_back(cloud);
        const double c = coverage(only, s.camera, 32);
        EXPECT_GT(c, 0.05) << knob;
        EXPECT_LT(c, 0.45) << knob;
    }
}

TEST(StressKnobs, StreamlineWidthIsThePixelWidthAtEveryVertex) {
    for (double knob : {0.25, 0.5, 1.0, 2.0, 4.0, 0.1, 16.0}) {
        const StressScene s = stress::make("streamlines", knob, size(64, 80));
        const SceneObject& lines = objectWith(s, Representation::Lines);
        EXPECT_GE(lines.vertexCount() - lines.indices.size(), 20u);  // one fewer segment than vertices per line
        EXPECT_LE(lines.vertexCount() - lines.indices.size(), 40u);
        for (std::size_t i = 0; i < lines.vertexCount(); ++i) {
            const double depth = s.camera.depthOf(vertex(lines, i));
            ASSERT_NEAR(2.0 * radiusOf(lines, i) / s.camera.pixelSizeAt(depth), knob, 1e-5 * knob);
        }
        const ScalarField* time = lines.field("time");
        ASSERT_NE(time, nullptr);
        EXPECT_EQ(s.colorField, "time");
    }
}

TEST(StressKnobs, GrazingAngleIsBetweenTheCentreRayAndThePlaneNormal) {
    for (double knob : {80.0, 82.0, 84.0, 86.0, 88.0, 89.0, 89.5, 0.0, 45.0}) {
        const StressScene s = stress::make("grazing", knob, size(64, 48));
        const SceneObject& plane = s.scene->objects.at(0);
        const Vec3 a = vertex(plane, plane.indices[0]), b = vertex(plane, plane.indices[1]),
                   c = vertex(plane, plane.indices[2]);
        const Vec3 n = normalize(cross(b - a, c - a));
        Vec3 o, d;
        s.camera.ray(32, 24, o, d);
        const double angle = std::acos(std::abs(dot(normalize(d), n))) * 180.0 / kPi;
        EXPECT_NEAR(angle, knob, 1e-6);
        // Every vertex of the plane lies in the same plane.
        for (std::size_t i = 0; i < plane.vertexCount(); ++i) ASSERT_NEAR(dot(vertex(plane, i) - a, n), 0.0, 1e-9);
        // The centre ray meets it at the focal distance.
        EXPECT_NEAR(castRay(*s.scene, o, d), s.focalDistance, 1e-3 * s.focalDistance);
    }
}

TEST(StressKnobs, SlabGapIsTheKnobTimesTheAoRadius) {
    for (double knob : {0.05, 0.1, 0.25, 0.5, 1.0, 2.0, 0.01, 10.0}) {
        const StressScene s = stress::make("slabs", knob, size(64, 64));
        const SceneObject& wall = objectNamed(s, "wall");
        const SceneObject& slab = objectNamed(s, "slab");
        const Vec3 w0 = vertex(wall, 0);
        const Vec3 n = normalize(cross(vertex(wall, wall.indices[1]) - w0, vertex(wall, wall.indices[2]) - w0));
        double lo = 1e300, hi = -1e300;
        for (std::size_t i = 0; i < slab.vertexCount(); ++i) {
            const double h = std::abs(dot(vertex(slab, i) - w0, n));
            lo = std::min(lo, h), hi = std::max(hi, h);
        }
        EXPECT_NEAR(lo, knob * s.aoRadius, 1e-5);
        EXPECT_NEAR(hi - lo, 0.02 * s.aoRadius, 1e-5);  // thickness
        // The wall shows around the slab: rays at the image corners hit it
        // farther away than the slab at the centre.
        Vec3 o, d;
        s.camera.ray(32, 32, o, d);
        const double centre = castRay(*s.scene, o, d);
        s.camera.ray(1, 1, o, d);
        EXPECT_GT(castRay(*s.scene, o, d), centre);
    }
}

TEST(StressKnobs, StaircaseStepHeightIsTheKnobTimesTheAoRadius) {
    for (double knob : {0.25, 0.5, 1.0, 2.0, 4.0, 0.1, 10.0}) {
        const StressScene s = stress::make("staircase", knob, size(64, 64));
        // Heights of the horizontal faces (treads, floor): equally spaced.
        std::set<double> levels;
        for (const auto& o : s.scene->objects)
            for (std::size_t t = 0; t < o.indices.size(); t += 3) {
                const Vec3 a = vertex(o, o.indices[t]), b = vertex(o, o.indices[t + 1]), c = vertex(o, o.indices[t + 2]);
                if (std::abs(a.y - b.y) < 1e-9 && std::abs(a.y - c.y) < 1e-9) levels.insert(std::round(a.y * 1e5) / 1e5);
            }
        ASSERT_GE(levels.size(), 4u);
        std::vector<double> v(levels.begin(), levels.end());
        for (std::size_t i = 1; i < v.size(); ++i) EXPECT_NEAR(v[i] - v[i - 1], knob * s.aoRadius, 1e-4);
        // Seen from above and in front, the image centre's depth jumps
        // somewhere along the image's vertical centre line (a riser hidden
        // behind a tread edge) by about a step.
        double biggestJump = 0, previous = 0;
        for (int y = 0; y < 64; ++y) {
            Vec3 o, d;
            s.camera.ray(32, y + 0.5, o, d);
            const double t = castRay(*s.scene, o, d);
            ASSERT_LT(t, kMiss);
            if (y > 0) biggestJump = std::max(biggestJump, previous - t);
            previous = t;
        }
        EXPECT_GT(biggestJump, 0.5 * knob * s.aoRadius);
    }
}

TEST(StressKnobs, StripePeriodAtTheImageCentreIsTheKnobInPixels) {
    for (double knob : {1.5, 2.0, 3.0, 4.0, 8.0, 1.0, 64.0}) {
        const StressScene s = stress::make("stripes", knob, size(512, 512));
        const SceneObject& plane = s.scene->objects.at(0);
        const ScalarField* stripe = plane.field("stripe");
        ASSERT_NE(stripe, nullptr);
        EXPECT_EQ(stripe->association, ScalarField::Association::Cell);
        for (float v : stripe->values) ASSERT_TRUE(v == 0.f || v == 1.f);
        // Ground hit of the centre ray, then the boundaries (vertex rows)
        // just before and after it, projected back to the image.
        Vec3 o, d;
        s.camera.ray(256, 256, o, d);
        const Vec3 hit = o + d * castRay(*s.scene, o, d);
        // Boundary rows are at constant z: the nearest on either side of the hit.
        double nearest = 1e300, after = -1e300;
        for (std::size_t i = 0; i < plane.vertexCount(); ++i) {
            const double z = vertex(plane, i).z;
            if (z >= hit.z) nearest = std::min(nearest, z);
            if (z < hit.z) after = std::max(after, z);
        }
        double px0, py0, px1, py1;
        ASSERT_TRUE(project(s.camera, {0, 0, nearest}, px0, py0));
        ASSERT_TRUE(project(s.camera, {0, 0, after}, px1, py1));
        EXPECT_NEAR(py0 - py1, knob, 0.03 * knob);
        // Neighbouring strips alternate.
        EXPECT_NE(stripe->values.at(0), stripe->values.at(2));
    }
}

TEST(StressKnobs, ListedValuesAreInsideTheAcceptedRange) {
    for (const auto& family : stress::families())
        for (double k : stress::knobValues(family)) EXPECT_NO_THROW(stress::make(family, k, size(16, 16))) << family;
    EXPECT_EQ(stress::knobValues("particles"), (std::vector<double>{0.5, 1, 2, 4, 8, 20}));
    EXPECT_EQ(stress::knobValues("streamlines"), (std::vector<double>{0.25, 0.5, 1, 2, 4}));
    EXPECT_EQ(stress::knobValues("slabs"), (std::vector<double>{0.05, 0.1, 0.25, 0.5, 1, 2}));
    EXPECT_EQ(stress::knobValues("staircase"), (std::vector<double>{0.25, 0.5, 1, 2, 4}));
    EXPECT_EQ(stress::knobValues("grazing"), (std::vector<double>{80, 82, 84, 86, 88, 89}));
    EXPECT_EQ(stress::knobValues("stripes"), (std::vector<double>{1.5, 2, 3, 4, 8}));
    for (const char* f : {"plane", "corner", "terrain", "border", "gyroid"})
        EXPECT_EQ(stress::knobValues(f), std::vector<double>{0}) << f;
}

TEST(StressKnobs, NamesCarryTheKnob) {
    EXPECT_EQ(stress::make("particles", 0.5, size(16, 16)).name, "particles-r0.5");
    EXPECT_EQ(stress::make("grazing", 89, size(16, 16)).name, "grazing-89");
    EXPECT_EQ(stress::make("plane", 0, size(16, 16)).name, "plane");
    EXPECT_EQ(stress::make("particles", 0.5, size(16, 16)).knob, "projected radius (px)");
}

// The message of the darkroom::Error thrown by f, or "" if none.
template <class F>
std::string errorOf(F f) {
    try {
        f();
    } catch (const Error& e) {
        return e.what();
    }
    return "";
}

TEST(StressKnobs, BadFamiliesAndKnobsAreErrorsNamingTheFamily) {
    const std::string unknown = errorOf([] { stress::make("teapot", 0); });
    EXPECT_NE(unknown.find("teapot"), std::string::npos) << unknown;
    EXPECT_NE(unknown.find("particles"), std::string::npos) << unknown;  // lists the known ones
    EXPECT_NE(unknown.find("stripes"), std::string::npos) << unknown;
    EXPECT_NE(errorOf([] { stress::knobValues("teapot"); }).find("teapot"), std::string::npos);
    EXPECT_NE(errorOf([] { stress::sweep("teapot"); }).find("teapot"), std::string::npos);

    struct Bad {
        const char* family;
        double knob;
        const char* range;
    };
    for (const Bad& b : {Bad{"particles", 0.2, "[0.25, 64]"}, Bad{"particles", 65, "[0.25, 64]"},
                         Bad{"streamlines", 0.05, "[0.1, 16]"}, Bad{"slabs", 11, "[0.01, 10]"},
                         Bad{"staircase", 0.0, "[0.1, 10]"}, Bad{"grazing", 90, "[0, 89.5]"},
                         Bad{"grazing", -1, "[0, 89.5]"}, Bad{"stripes", 0.5, "[1, 64]"},
                         Bad{"stripes", std::nan(""), "[1, 64]"}}) {
        const std::string m = errorOf([&] { stress::make(b.family, b.knob); });
        EXPECT_NE(m.find(b.family), std::string::npos) << m;
        EXPECT_NE(m.find(b.range), std::string::npos) << m;
    }
    const std::string noKnob = errorOf([] { stress::make("corner", 1.0); });
    EXPECT_NE(noKnob.find("corner"), std::string::npos) << noKnob;
    EXPECT_NE(noKnob.find("0"), std::string::npos) << noKnob;
    const std::string badSize = errorOf([] { stress::make("plane", 0, size(0, 10)); });
    EXPECT_NE(badSize.find("plane"), std::string::npos) << badSize;
}

}  // namespace
