#pragma once
// Runs one of this plugin's nodes through the registry.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/run_filter.h>

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace darkroom::test {

using Inputs = std::map<std::string, std::vector<Value>>;

inline FilterRunResult runNode(const std::string& type, Inputs inputs, int threads = 2) {
    auto f = pluginRegistry().createFilter(type);
    FilterRunOptions o;
    o.threads = threads;
    return runFilter(*f, inputs, o);
}

inline BufferPtr runImage(const std::string& type, Inputs inputs, int threads = 2) {
    return runNode(type, std::move(inputs), threads).outputs.at("image").asImage();
}

// The message of the darkroom::Error the node throws, or "no error".
inline std::string errorOf(const std::string& type, Inputs inputs) {
    try {
        runNode(type, std::move(inputs));
    } catch (const Error& e) {
        return e.what();
    }
    return "no error";
}

inline const float kInf = std::numeric_limits<float>::infinity();
inline const float kNaN = std::numeric_limits<float>::quiet_NaN();

}  // namespace darkroom::test
