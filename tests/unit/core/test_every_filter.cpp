// Every registered filter, whatever plugin it comes from, goes through
// describe, a YAML round trip and execution on a tiny synthetic input with
// finite outputs. A new plugin is covered the day it registers; one that needs
// files to run gets a setup entry in fixtureFor() below.
#include "test_support.h"

#include <darkroom/data/cinema/writer.h>
#include <darkroom/data/image_io.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/core/run_filter.h>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>

using namespace darkroom;

namespace {

Registry& registry() { return test::pluginRegistry(); }

// 5x4 image: Z with one background pixel, colour, and every channel any
// registered port asks for.
BufferPtr syntheticImage(const std::vector<std::string>& extra) {
    std::vector<std::string> channels = {"Z", "R", "G", "B", "A", "value"};
    for (const auto& c : extra)
        if (std::find(channels.begin(), channels.end(), c) == channels.end()) channels.push_back(c);
    auto b = test::makeImage(5, 4, channels, [&](int x, int y, int c) -> float {
        if (channels[c] == "Z") return (x == 4 && y == 0) ? std::numeric_limits<float>::infinity() : 2.0f + 0.1f * x;
        return 0.2f + 0.1f * float((x + 2 * y + c) % 7);
    });
    Camera cam;
    cam.width = 5;
    cam.height = 4;
    cam.position = {0, 0, 4};
    b->metadata().camera = cam;
    return b;
}

// Files and parameters a type needs before it can run.
using Fixture = std::function<void(const test::TempDir&, std::map<std::string, std::vector<Value>>&)>;
Fixture fixtureFor(const std::string& type) {
    if (type == "ImageReader")
        return [](const test::TempDir& dir, auto& in) {
            writeImage(*syntheticImage({}), dir.file("in.exr"));
            in["path"] = {Value(dir.file("in.exr"))};
        };
    if (type == "ImageWriter")
        return [](const test::TempDir& dir, auto& in) { in["path"] = {Value(dir.file("out.exr"))}; };
    if (type == "Mix")  // the factor channel is a parameter; the synthetic image has "value"
        return [](const test::TempDir&, auto& in) { in["factorChannel"] = {Value("value")}; };
    if (type == "CinemaReader")
        return [](const test::TempDir& dir, auto& in) {
            CinemaWriter w(dir.file("tiny.cdb"), {"phi"});
            w.addEntry({{"phi", CinemaValue(0.0)}}, *syntheticImage({}));
            w.finish();
            in["database"] = {Value(dir.file("tiny.cdb"))};
        };
    if (type == "CinemaWriter")
        return [](const test::TempDir& dir, auto& in) {
            in["row"] = {Value("phi=0")};
            in["database"] = {Value(dir.file("written.cdb"))};
        };
    if (type == "Spheres" || type == "PointListAO")
        return [](const test::TempDir& dir, auto& in) {
            test::writeText(dir.file("points.csv"), "x,y,z,radius,value\n0,0,2,0.5,1\n");
            in["points"] = {Value(dir.file("points.csv"))};
        };
    if (type == "Movie")
        return [](const test::TempDir& dir, auto& in) {
            CinemaWriterOptions o;
            o.productExtension = ".png";
            CinemaWriter w(dir.file("frames.cdb"), {"time"}, o);
            w.addEntry({{"time", CinemaValue(0.0)}}, *syntheticImage({}));
            w.addEntry({{"time", CinemaValue(1.0)}}, *syntheticImage({}));
            w.finish();
            in["database"] = {Value(dir.file("frames.cdb"))};
            in["path"] = {Value(dir.file("frames.mp4"))};
        };
    if (type == "Capture")
        return [](const test::TempDir& dir, auto& in) {
            test::writeText(dir.file("scene.yaml"),
                            "objects:\n  - generator: particles\n    parameters: {count: 20}\n"
                            "cameras:\n  resolution: [6, 5]\n  grid: {phi: 1, theta: 1}\n");
            in["scene"] = {Value(dir.file("scene.yaml"))};
        };
    return {};
}

class EveryFilter : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryFilter, DescribesItself) {
    const RegisteredFilter* f = registry().filter(GetParam());
    ASSERT_NE(f, nullptr);
    EXPECT_FALSE(f->info.doc.empty()) << "a type needs documentation";
    EXPECT_FALSE(f->info.category.empty());
    const PortList& ports = registry().ports(GetParam());
    for (const auto& p : ports.inputs) {
        EXPECT_FALSE(p.doc.empty()) << "input '" << p.name << "' needs documentation";
        if (p.type == PortType::Image) continue;
        ASSERT_FALSE(p.defaultValue.empty()) << "value input '" << p.name << "' needs a default";
        EXPECT_NO_THROW(checkValue(p, p.defaultValue)) << "default of '" << p.name << "' violates its own range";
    }
    for (const auto& p : ports.outputs) EXPECT_FALSE(p.doc.empty()) << "output '" << p.name << "'";
}

TEST_P(EveryFilter, RoundTripsThroughYaml) {
    Graph g(registry());
    g.addNode("node", GetParam());
    for (const auto& p : registry().ports(GetParam()).inputs)
        if (p.type != PortType::Image) g.setParameter("node", p.name, p.defaultValue);
    const std::string text = serializePipeline(g);
    Diagnostics d;
    Graph back = parsePipeline(text, "roundtrip.yaml", registry(), d);
    for (const auto& x : d) ADD_FAILURE() << x.str() << "\n" << text;
    EXPECT_EQ(serializePipeline(back), text);
    ASSERT_NE(back.node("node"), nullptr);
    EXPECT_EQ(back.node("node")->parameters.size(), g.node("node")->parameters.size());
    for (const auto& [k, v] : g.node("node")->parameters)
        EXPECT_TRUE(*back.node("node")->parameter(k) == v) << k;
}

TEST_P(EveryFilter, RunsOnATinySyntheticInputWithFiniteOutputs) {
    const PortList& ports = registry().ports(GetParam());
    test::TempDir dir;
    std::map<std::string, std::vector<Value>> inputs;
    for (const auto& p : ports.inputs) {
        if (p.type != PortType::Image) continue;
        const BufferPtr img = syntheticImage(p.channels);
        inputs[p.name] = p.multiple ? std::vector<Value>{Value(img), Value(syntheticImage(p.channels))}
                                    : std::vector<Value>{Value(img)};
    }
    if (Fixture f = fixtureFor(GetParam())) f(dir, inputs);
    std::unique_ptr<Filter> filter = registry().createFilter(GetParam());
    FilterRunOptions o;
    o.threads = 2;
    o.registry = &registry();
    o.inputBase = dir.path();
    o.outputDir = dir.path();
    FilterRunResult r;
    ASSERT_NO_THROW(r = runFilter(*filter, inputs, o));
    for (const auto& out : ports.outputs) {
        ASSERT_TRUE(r.outputs.count(out.name)) << out.name;
        if (out.type != PortType::Image) continue;
        const BufferPtr& b = r.outputs[out.name].asImage();
        ASSERT_NE(b, nullptr);
        // Only Z may be +inf (background), and NaN ("no data") only on background.
        const float* z = b->hostFloat("Z");
        for (const auto& c : b->channels()) {
            if (c.type != ChannelType::Float32) continue;
            const float* p = b->hostFloat(c.name);
            for (std::size_t i = 0; i < b->pixelCount(); ++i) {
                const bool background = z && z[i] == std::numeric_limits<float>::infinity();
                const bool ok = std::isfinite(p[i]) || (c.name == "Z" && background) ||
                                (std::isnan(p[i]) && background);
                ASSERT_TRUE(ok) << "output '" << out.name << "' channel " << c.name << " pixel " << i << " = " << p[i];
            }
        }
    }
}

std::vector<std::string> allTypes() {
    std::vector<std::string> out;
    for (const auto* f : registry().filters()) out.push_back(f->info.type);
    return out;
}

INSTANTIATE_TEST_SUITE_P(Registered, EveryFilter, ::testing::ValuesIn(allTypes()),
                         [](const ::testing::TestParamInfo<std::string>& i) { return i.param; });
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(EveryFilter);

TEST(EveryFilterSuite, FindsThePluginsOfThisBuild) {
    for (const char* t : {"ImageReader", "ImageWriter", "ColorMapping"})
        EXPECT_NE(registry().filter(t), nullptr) << t << " should be registered by this build's plugins";
}

}  // namespace
