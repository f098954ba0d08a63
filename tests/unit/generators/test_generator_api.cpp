#include "mesh_checks.h"

#include <darkroom/error.h>
#include <darkroom/scene/generators.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using ::testing::AllOf;
using ::testing::HasSubstr;

namespace {

// The message of the Error generate() throws, or "" if it does not throw.
std::string errorOf(const std::string& name, const std::map<std::string, std::string>& params) {
    try {
        generate(name, params);
    } catch (const Error& e) {
        return e.what();
    }
    return {};
}

// Point data: one value per vertex; cell data: one per cell of primitiveCell,
// or one per primitive when that map is empty.
std::size_t expectedFieldSize(const SceneObject& o, const ScalarField& f) {
    if (f.association == ScalarField::Association::Point) return o.vertexCount();
    if (!o.primitiveCell.empty()) return *std::max_element(o.primitiveCell.begin(), o.primitiveCell.end()) + 1;
    switch (o.representation) {
        case Representation::Surface: return o.indices.size() / 3;
        case Representation::Lines: return o.indices.size();
        case Representation::Points: return o.vertexCount();
    }
    return 0;
}

}  // namespace

TEST(Generators, EveryNameWorksWithDefaults) {
    const auto names = generatorNames();
    for (const char* expected : {"isosurface", "streamlines", "particles", "maxima", "plane", "demo"})
        EXPECT_NE(std::find(names.begin(), names.end(), expected), names.end()) << expected;
    for (const auto& name : names) {
        const auto objects = generate(name, {});
        ASSERT_FALSE(objects.empty()) << name;
        for (const auto& o : objects) {
            EXPECT_GT(o.vertexCount(), 0u) << name;
            EXPECT_EQ(o.vertices.size() % 4, 0u);
            for (const auto& f : o.fields) EXPECT_EQ(f.values.size(), expectedFieldSize(o, f)) << name << " " << f.name;
        }
    }
}

TEST(Generators, DemoHasAllFourObjectsInsideTheCube) {
    const auto objects = generate("demo", {});
    ASSERT_EQ(objects.size(), 4u);
    EXPECT_EQ(objects[0].name, "isosurface");
    EXPECT_EQ(objects[1].name, "streamlines");
    EXPECT_EQ(objects[2].name, "particles");
    EXPECT_EQ(objects[3].name, "maxima");
    Scene scene;
    scene.objects = objects;
    const Bounds b = scene.bounds();
    EXPECT_GE(b.lo.x, -1.1);
    EXPECT_LE(b.hi.z, 1.1);
    EXPECT_GT(b.radius(), 1.0);
    EXPECT_EQ(generate("demo", {{"streamlines", "0"}})[1].vertexCount(), 0u);
}

TEST(Generators, BadParametersNameGeneratorKeyAndExpectation) {
    EXPECT_THAT(errorOf("isosurface", {{"resolution", "-3"}}),
                AllOf(HasSubstr("isosurface"), HasSubstr("'resolution'"), HasSubstr("integer between 2 and 512"),
                      HasSubstr("-3")));
    EXPECT_THAT(errorOf("isosurface", {{"resolution", "12.5"}}), HasSubstr("integer"));
    EXPECT_THAT(errorOf("isosurface", {{"resolutoin", "12"}}),
                AllOf(HasSubstr("isosurface"), HasSubstr("unknown parameter 'resolutoin'"), HasSubstr("resolution")));
    EXPECT_THAT(errorOf("streamlines", {{"step", "fast"}}),
                AllOf(HasSubstr("streamlines"), HasSubstr("'step'"), HasSubstr("must be a number"), HasSubstr("fast")));
    EXPECT_THAT(errorOf("streamlines", {{"step", "0.1x"}}), HasSubstr("must be a number"));
    EXPECT_THAT(errorOf("streamlines", {{"step", ""}}), HasSubstr("must be a number"));
    EXPECT_THAT(errorOf("streamlines", {{"direction", "sideways"}}),
                AllOf(HasSubstr("'direction'"), HasSubstr("forward, backward, both")));
    EXPECT_THAT(errorOf("streamlines", {{"length", "1000"}, {"step", "0.0001"}}),
                AllOf(HasSubstr("'length'"), HasSubstr("more than 1000000")));
    EXPECT_THAT(errorOf("particles", {{"count", "-1"}}), AllOf(HasSubstr("particles"), HasSubstr("'count'")));
    EXPECT_THAT(errorOf("particles", {{"radius", "nan"}}), HasSubstr("'radius'"));
    EXPECT_THAT(errorOf("maxima", {{"radius", "-0.1"}}), AllOf(HasSubstr("maxima"), HasSubstr("'radius'")));
    EXPECT_THAT(errorOf("plane", {{"normal", "0 0"}}), AllOf(HasSubstr("plane"), HasSubstr("three numbers")));
    EXPECT_THAT(errorOf("plane", {{"normal", "0 0 0"}}), HasSubstr("zero vector"));
    EXPECT_THAT(errorOf("demo", {{"colour", "red"}}), AllOf(HasSubstr("demo"), HasSubstr("'colour'")));
    EXPECT_THAT(errorOf("teapot", {}), AllOf(HasSubstr("unknown generator 'teapot'"), HasSubstr("isosurface")));
}

TEST(Generators, NumbersAcceptCommonSpellings) {
    EXPECT_EQ(generate("isosurface", {{"resolution", " 16 "}})[0].indices,
              generate("isosurface", {{"resolution", "1.6e1"}})[0].indices);
    EXPECT_NO_THROW(generate("plane", {{"center", "[0, 0, -1.2]"}, {"normal", "0,0,1"}}));
    EXPECT_NO_THROW(generate("streamlines", {{"step", "+0.1"}, {"count", "2"}}));
}

TEST(Plane, FacesItsNormalWithTheRequestedSize) {
    const SceneObject o =
        generate("plane", {{"size", "4"}, {"center", "1 2 3"}, {"normal", "0 1 0"}, {"subdivisions", "3"}}).at(0);
    EXPECT_EQ(o.vertexCount(), 16u);
    EXPECT_EQ(o.indices.size(), 9u * 2 * 3);
    double area = 0;
    for (std::size_t t = 0; t < o.indices.size() / 3; ++t) {
        const Vec3 n = test::triangleNormal(o, t);
        EXPECT_NEAR(normalize(n).y, 1.0, 1e-6);
        area += length(n) / 2;
    }
    EXPECT_NEAR(area, 16.0, 1e-4);
    for (std::size_t i = 0; i < o.vertexCount(); ++i) EXPECT_NEAR(o.vertices[i * 4 + 1], 2.0, 1e-6);
}
