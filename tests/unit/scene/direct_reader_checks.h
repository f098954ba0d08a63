#pragma once
// What the tests of the direct mesh readers (ply_direct_test.cpp,
// vtk_legacy_direct_test.cpp) share: the same objects bit for bit, the
// general reader forced or the direct reader's windows shrunk through a
// reader's options, the direct reader alone, and a limit set for a scope.
#include <darkroom/limits.h>
#include <darkroom/scene.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace darkroom::test {

// Sets a limit while it lives and restores the one before.
class ScopedLimit {
public:
    ScopedLimit(Limit which, std::uint64_t value) : which_(which), before_(limit(which)) { setLimit(which, value); }
    ~ScopedLimit() { setLimit(which_, before_); }
    ScopedLimit(const ScopedLimit&) = delete;
    ScopedLimit& operator=(const ScopedLimit&) = delete;

private:
    Limit which_;
    std::uint64_t before_;
};

// Floats as their bits: NaNs compare, and -0 differs from +0.
inline std::vector<std::uint32_t> bits(const std::vector<float>& v) {
    std::vector<std::uint32_t> out(v.size());
    if (!v.empty()) std::memcpy(out.data(), v.data(), 4 * v.size());
    return out;
}

inline void expectSameObjects(const std::vector<SceneObject>& a, const std::vector<SceneObject>& b) {
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t k = 0; k < a.size(); ++k) {
        EXPECT_EQ(a[k].name, b[k].name);
        EXPECT_EQ(a[k].representation, b[k].representation);
        EXPECT_EQ(bits(a[k].vertices), bits(b[k].vertices));
        EXPECT_EQ(a[k].indices, b[k].indices);
        EXPECT_EQ(a[k].primitiveCell, b[k].primitiveCell);
        ASSERT_EQ(a[k].fields.size(), b[k].fields.size());
        for (std::size_t f = 0; f < a[k].fields.size(); ++f) {
            EXPECT_EQ(a[k].fields[f].name, b[k].fields[f].name);
            EXPECT_EQ(a[k].fields[f].association, b[k].fields[f].association);
            EXPECT_EQ(bits(a[k].fields[f].values), bits(b[k].fields[f].values)) << a[k].fields[f].name;
        }
    }
}

// A reader's options (PlyReadOptions, VtkLegacyReadOptions) with the
// general reader forced, or with the direct reader's windows of `bytes`.
template <class Options>
Options generalReader() {
    Options o;
    o.direct = false;
    return o;
}
template <class Options>
Options windowsOf(std::size_t bytes) {
    Options o;
    o.windowBytes = bytes;
    return o;
}

// `read(path, options)` with the general reader shut out: --max-input-bytes
// (the largest file read whole) set to 1 byte, which only the direct
// reader, never holding the file whole, gets past.
template <class Read, class Options>
std::vector<SceneObject> readDirectOnly(Read read, const std::string& path, const Options& options) {
    const ScopedLimit wholeFiles(Limit::InputBytes, 1);
    return read(path, options);
}

}  // namespace darkroom::test
