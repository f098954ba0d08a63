#pragma once
// FNV-1a over text: it tells changed content from unchanged (a scene file, a
// node's parameters) for the origin a database records; it is not meant to
// resist a forger.
#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <string_view>

namespace darkroom::workflows {

struct ContentHash {
    std::uint64_t h = 0xcbf29ce484222325ull;
    void add(std::string_view s) {
        for (unsigned char c : s) h = (h ^ c) * 0x100000001b3ull;
        h = (h ^ 0xff) * 0x100000001b3ull;  // a separator, so ("ab","c") differs from ("a","bc")
    }
    void add(double v) { add(fmt::format("{}", v)); }
    std::string hex() const { return fmt::format("{:016x}", h); }
};

}  // namespace darkroom::workflows
