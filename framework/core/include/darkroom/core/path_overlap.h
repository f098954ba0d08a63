#pragma once
// Whether an output path would write over an input: the one check shared by
// the evaluator (an output resolved by a node against what its upstream
// nodes read) and the runner (a database a batch writes against the
// database it reads), so both refuse the same cases with the same words.
#include <darkroom/export.h>

#include <string>

namespace darkroom {

// `path` made absolute and lexically normal, without a trailing '/'.
DARKROOM_API std::string absoluteNormal(const std::string& path);

// True when writing `output` could change `input`: the same path, or one of
// them a folder holding the other (compared as absolute, normal paths; links
// are not followed, so two names of one folder are not caught).
DARKROOM_API bool pathsOverlap(const std::string& output, const std::string& input);

// "is", "holds" or "lies inside", as `output` relates to `input`, for messages.
DARKROOM_API std::string overlapWording(const std::string& output, const std::string& input);

}  // namespace darkroom
