#pragma once
// Running the registered FXAA filter on small images made in code.
#include "test_support.h"

#include <darkroom/core/run_filter.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace darkroom::test {

using Inputs = std::map<std::string, std::vector<Value>>;
inline const float kNaN = std::numeric_limits<float>::quiet_NaN();
inline const float kInf = std::numeric_limits<float>::infinity();

inline BufferPtr runFxaa(const BufferPtr& image, Inputs params = {}, int threads = 2) {
    auto f = pluginRegistry().createFilter("FXAA");
    params["image"] = {Value(image)};
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, params, o).outputs.at("image").asImage();
}

// A grey image: R = G = B = fn(x, y), and A = 1 when withAlpha.
inline std::shared_ptr<WritableBuffer> greyImage(int w, int h, const std::function<float(int, int)>& fn,
                                                 bool withAlpha = false) {
    std::vector<std::string> names{"R", "G", "B"};
    if (withAlpha) names.push_back("A");
    return makeImage(w, h, names, [&](int x, int y, int c) { return c == 3 ? 1.0f : fn(x, y); });
}

inline float at(const Buffer& b, const char* channel, int x, int y) {
    return b.hostFloat(channel)[std::size_t(y) * std::size_t(b.width()) + std::size_t(x)];
}

}  // namespace darkroom::test
