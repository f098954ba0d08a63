#include "mesh_checks.h"

#include <darkroom/scene/generators.h>

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using darkroom::test::vertexAt;

TEST(Particles, CountRadiusAndFieldsAreRespected) {
    const SceneObject o = generate("particles", {{"count", "500"}, {"radius", "0.02"}}).at(0);
    EXPECT_EQ(o.representation, Representation::Points);
    ASSERT_EQ(o.vertexCount(), 500u);
    EXPECT_TRUE(o.indices.empty());
    ASSERT_NE(o.field("value"), nullptr);
    ASSERT_NE(o.field("id"), nullptr);
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        EXPECT_FLOAT_EQ(o.vertices[i * 4 + 3], 0.02f);
        EXPECT_EQ(o.field("id")->values[i], float(i));
        // A halo outside the default isosurface, so the surface does not hide it.
        const double f = generators::demoField(vertexAt(o, i));
        EXPECT_LT(f, 0.5);
        EXPECT_NEAR(o.field("value")->values[i], f, 1e-5);
    }
}

TEST(Particles, AreDeterministicAndDependOnTheSeed) {
    const auto a = generate("particles", {}).at(0);
    const auto b = generate("particles", {}).at(0);
    EXPECT_EQ(a.vertexCount(), 2000u);
    EXPECT_EQ(a.vertices, b.vertices);
    const auto c = generate("particles", {{"seed", "8"}}).at(0);
    EXPECT_NE(a.vertices, c.vertices);
    // A prefix of a larger cloud is the smaller cloud: particles are independent.
    const auto small = generate("particles", {{"count", "10"}}).at(0);
    EXPECT_TRUE(std::equal(small.vertices.begin(), small.vertices.end(), a.vertices.begin()));
}

TEST(Particles, ClusterNearTheBlobs) {
    const auto o = generate("particles", {}).at(0);
    // Uniform points in the cube have a mean field value of ~0.03; the halo's
    // density grows towards the surface.
    double mean = 0;
    for (float v : o.field("value")->values) mean += v;
    mean /= double(o.vertexCount());
    EXPECT_GT(mean, 0.15);
}

TEST(Maxima, AreLocalMaximaOfTheField) {
    const SceneObject o = generate("maxima", {}).at(0);
    EXPECT_EQ(o.representation, Representation::Points);
    // Four strong blobs (two merged), three weak ones and three on the ring.
    EXPECT_GE(o.vertexCount(), 9u);
    EXPECT_LE(o.vertexCount(), 11u);
    const auto& value = o.field("value")->values;
    ASSERT_EQ(value.size(), o.vertexCount());
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        const Vec3 m(o.vertices[i * 4], o.vertices[i * 4 + 1], o.vertices[i * 4 + 2]);
        const double f = generators::demoField(m);
        EXPECT_NEAR(value[i], f, 1e-6);
        EXPECT_LT(length(generators::demoFieldGradient(m)), 1e-4);
        for (int d = 0; d < 27; ++d) {
            if (d == 13) continue;
            const Vec3 dir = normalize(Vec3(d % 3 - 1, d / 3 % 3 - 1, d / 9 - 1));
            ASSERT_LT(generators::demoField(m + dir * 0.01), f) << "maximum " << i << " direction " << d;
        }
        if (i > 0) {
            EXPECT_LE(value[i], value[i - 1]) << "sorted highest first";
        }
    }
    // Some maxima are weak blobs outside the isosurface, visible in the demo.
    EXPECT_LT(value.back(), 0.5f);
    EXPECT_GT(value.front(), 0.9f);
}

TEST(Maxima, RadiusAndThreshold) {
    const SceneObject o = generate("maxima", {{"radius", "0.1"}, {"min value", "0.5"}}).at(0);
    ASSERT_GT(o.vertexCount(), 0u);
    for (std::size_t i = 0; i < o.vertexCount(); ++i) {
        EXPECT_FLOAT_EQ(o.vertices[i * 4 + 3], 0.1f);
        EXPECT_GE(o.field("value")->values[i], 0.5f);
    }
}
