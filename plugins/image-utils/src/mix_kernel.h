#pragma once
// Mix's arithmetic per pixel (mix.cpp) and for vectors of pixels
// (mix_simd.cpp): the same float operations in the same order, same bits.
#include <cstddef>

namespace darkroom::utils {

enum class MixOp { Multiply, Blend, Over, Add };

struct MixJob {
    MixOp op = MixOp::Multiply;
    float amount = 1.0f, keep = 0.0f;  // keep = 1 - amount
    const float* base[4] = {nullptr, nullptr, nullptr, nullptr};    // R, G, B, A (A may be null: opaque)
    const float* factor = nullptr;                                  // multiply
    const float* depth = nullptr;                                   // multiply: +inf = background (may be null)
    const float* second[4] = {nullptr, nullptr, nullptr, nullptr};  // blend, over, add (A may be null)
    float* out[4] = {nullptr, nullptr, nullptr, nullptr};           // A only when base has A
};

void mixAt(const MixJob& job, std::size_t i);
// [begin, end) with the best SIMD instructions of the CPU; returns end, or
// begin when the span is shorter than a vector (then mixAt does it).
std::size_t mixSpan(const MixJob& job, std::size_t begin, std::size_t end);

}  // namespace darkroom::utils
