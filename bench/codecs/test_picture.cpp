#include "test_picture.h"

#include <algorithm>
#include <cmath>

namespace darkroom::bench {

namespace {

// ParaView's cool-to-warm end points and middle, linear RGB, interpolated
// linearly (close enough to the diverging map for compression purposes).
void coolToWarm(float t, float rgb[3]) {
    static const float stops[3][3] = {{0.230f, 0.299f, 0.754f}, {0.865f, 0.865f, 0.865f}, {0.706f, 0.016f, 0.150f}};
    const float s = std::clamp(t, 0.0f, 1.0f) * 2.0f;
    const int i = std::min(int(s), 1);
    const float f = s - float(i);
    for (int c = 0; c < 3; ++c) rgb[c] = stops[i][c] * (1 - f) + stops[i + 1][c] * f;
}

unsigned char srgb8(float linear) {
    const float v = std::clamp(linear, 0.0f, 1.0f);
    const float e = v <= 0.0031308f ? 12.92f * v : 1.055f * std::pow(v, 1.0f / 2.4f) - 0.055f;
    return static_cast<unsigned char>(std::lround(e * 255.0f));
}

}  // namespace

std::vector<unsigned char> colourMappedPicture(int size) {
    std::vector<unsigned char> px(std::size_t(size) * std::size_t(size) * 4, 0);
    const float r = 0.38f, pixel = 2.0f / float(size);
    for (int y = 0; y < size; ++y)
        for (int x = 0; x < size; ++x) {
            const float u = (float(x) + 0.5f) * pixel - 1.0f, v = (float(y) + 0.5f) * pixel - 1.0f;
            // A sphere (shaded) and a horizontal band below it (flat lit).
            const float d = std::sqrt(u * u + (v + 0.15f) * (v + 0.15f));
            const float sphere = std::clamp((r * 2.0f - d) / pixel + 0.5f, 0.0f, 1.0f);
            const float band = std::clamp((0.08f - std::abs(v - 0.72f)) / pixel + 0.5f, 0.0f, 1.0f) *
                               std::clamp((0.85f - std::abs(u)) / pixel + 0.5f, 0.0f, 1.0f);
            const float coverage = std::max(sphere, band);
            if (coverage <= 0) continue;
            const float z = std::sqrt(std::max(0.0f, 1.0f - (d / (r * 2)) * (d / (r * 2))));
            const float shade = sphere > 0 ? 0.25f + 0.75f * z : 0.8f;
            const float field = 0.5f + 0.5f * std::sin(3.0f * u + 2.0f * std::cos(2.5f * v));
            float rgb[3];
            coolToWarm(field, rgb);
            unsigned char* p = &px[(std::size_t(y) * std::size_t(size) + std::size_t(x)) * 4];
            for (int c = 0; c < 3; ++c) p[c] = srgb8(rgb[c] * shade);
            p[3] = static_cast<unsigned char>(std::lround(coverage * 255.0f));
        }
    return px;
}

}  // namespace darkroom::bench
