#pragma once
// The passes' SIMD kernels are compiled for several instruction sets (SSSE3
// ... AVX-512) and the best one the CPU has is chosen at run time. A pass's
// pixels must not depend on that choice: resultsPerSimdTarget runs `compute`
// once with each instruction set this CPU has, forcing Highway's choice, so a
// test can compare the results bit for bit. Shared by the passes' tests.
#include <hwy/targets.h>

#include <string>
#include <utility>
#include <vector>

namespace darkroom::test {

template <class Compute>
auto resultsPerSimdTarget(Compute compute) {
    std::vector<std::pair<std::string, decltype(compute())>> results;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        results.emplace_back(hwy::TargetName(target), compute());
    }
    hwy::SetSupportedTargetsForTest(0);  // back to the CPU's own choice
    return results;
}

}  // namespace darkroom::test
