#pragma once
// What every fuzz harness shares. A harness feeds one input to one reader and
// accepts only darkroom::Error (the readers' documented failure): any other
// exception, a signal, a sanitizer report, a timeout or an allocation beyond
// libFuzzer's -malloc_limit_mb is a finding.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>

namespace fuzz {

// The input as text (readers that take text in memory).
inline std::string_view text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// Writes the input to `name` in a folder of this process's own (harnesses of
// ctest -j and fuzz.sh runs share /tmp) and returns the path: for readers
// that take only a path. The folder is removed at exit.
std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name);

// This process's folder (created on first use).
const std::string& scratchFolder();

// A property the code under test promises (beyond not crashing): when it does
// not hold, the input is a finding like a crash.
inline void expect(bool holds, const char* property) {
    if (holds) return;
    std::fprintf(stderr, "fuzz harness: property broken: %s\n", property);
    std::abort();
}

}  // namespace fuzz
