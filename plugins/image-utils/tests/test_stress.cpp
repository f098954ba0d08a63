// Every node of this plugin on degenerate inputs: all background, 1x1, NaN
// and infinite depths and values. Outputs must be finite except Z (may be
// +inf) and NaN "no data" where Z is background; and deterministic across
// thread counts.
#include "run_node.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using namespace darkroom::test;

namespace {

// R, G, B, A, Z, AO, value; `kind` picks the degenerate content.
BufferPtr degenerate(int w, int h, int kind) {
    return makeImage(w, h, {"R", "G", "B", "A", "Z", "AO", "value"}, [=](int x, int y, int c) -> float {
        const bool bg = kind == 0 || (x + y) % 2 == 0;
        if (c == 4) return bg ? (kind == 2 && x % 3 == 1 ? kNaN : kInf) : 1.0f + float(x);
        if (c == 3) return bg ? 0.0f : 1.0f;
        if (c == 5) return bg ? kNaN : 0.5f;
        if (c == 6) return bg ? kNaN : (kind == 2 ? 1e30f : 2.0f);
        return bg ? 0.0f : 0.25f * float(c + 1);  // ColorMapping-style transparent black background
    });
}

void expectFinite(const Buffer& b, const std::string& what) {
    const float* z = b.hostFloat("Z");
    for (const auto& c : b.channels()) {
        if (c.type != ChannelType::Float32) continue;
        const float* p = b.hostFloat(c.name);
        for (std::size_t i = 0; i < b.pixelCount(); ++i) {
            const bool background = z && !std::isfinite(z[i]);
            const bool ok = std::isfinite(p[i]) || (background && (c.name == "Z" || std::isnan(p[i])));
            ASSERT_TRUE(ok) << what << ": " << c.name << " pixel " << i << " = " << p[i];
        }
    }
}

}  // namespace

TEST(ImageUtilsStress, DegenerateInputsGiveFiniteDeterministicOutputs) {
    const std::vector<std::pair<std::string, Inputs>> cases = {
        {"Mix", {}},
        {"Mix", {{"mode", {Value("over")}}, {"amount", {Value(0.5)}}}},
        {"Mix", {{"mode", {Value("blend")}}}},
        {"Mix", {{"mode", {Value("add")}}}},
        {"Background", {}},
        {"Background", {{"mode", {Value("color")}}}},
        {"ChannelSelect", {{"channels", {Value("R, value:S, Z")}}}},
        {"Resize", {{"scale", {Value(0.5)}}}},
        {"Resize", {{"scale", {Value(3.0)}}, {"filter", {Value("bilinear")}}}},
        {"Resize", {{"width", {Value(1)}}, {"height", {Value(1)}}}},
    };
    for (const auto& [w, h] : std::vector<std::pair<int, int>>{{1, 1}, {6, 5}})
        for (int kind = 0; kind < 3; ++kind)
            for (const auto& [type, params] : cases) {
                const BufferPtr in = degenerate(w, h, kind);
                Inputs p = params;
                p["image"] = {Value(in)};
                if (type == "Mix") p["other"] = {Value(degenerate(w, h, 2 - kind))};
                const std::string what = type + " " + std::to_string(w) + "x" + std::to_string(h) + " kind " +
                                         std::to_string(kind);
                const BufferPtr one = runImage(type, p, 1);
                expectFinite(*one, what);
                EXPECT_TRUE(identical(*one, *runImage(type, p, 4))) << what;
            }
}
