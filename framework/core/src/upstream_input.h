#pragma once
#include <string>

namespace darkroom {

// A file or folder a node upstream read (or resolved as an input path), and
// that node's name: what an output downstream must not write over.
struct UpstreamInput {
    std::string node;
    std::string path;  // absolute, lexically normal
};

}  // namespace darkroom
