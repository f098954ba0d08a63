#pragma once
// ColorMapping's per-object opacity (issue 30): "0: 0.3, 2: 1" gives the
// surfaces of object 0 opacity 0.3 and object 2 opacity 1; objects not
// listed keep 1. It multiplies the `opacity` port, so one slider still
// fades everything.
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace darkroom::colormapping {

class ObjectOpacity {
public:
    // Pairs "id: opacity" separated by commas (or semicolons); an id is a
    // non-negative integer, an opacity a number in [0, 1]. An empty text is
    // no per-object opacity. Throws darkroom::Error naming the bad pair.
    static ObjectOpacity parse(const std::string& text);
    bool empty() const { return byId_.empty(); }
    // The opacity of object `id` (1 when not listed).
    float operator()(std::uint32_t id) const;
    // Whether every listed object is opaque (then nothing changes).
    bool allOpaque() const;

private:
    std::vector<std::pair<std::uint32_t, float>> byId_;  // sorted by id
};

}  // namespace darkroom::colormapping
