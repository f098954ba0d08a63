#pragma once
// "node.port=value": a parameter set from text, typed by its port, as the
// runner's --set and scripts give it.
#include <darkroom/export.h>
#include <darkroom/core/graph.h>

#include <string>

namespace darkroom {

// Sets the parameter, parsing `assignment`'s value as the port's type.
// Throws InputError saying what is wrong: not node.port=value, no such node
// or input, a value of the wrong type, or an input an edge feeds (a value
// there would be ignored: the edge wins).
DARKROOM_API void assignParameter(Graph& graph, const std::string& assignment);

}  // namespace darkroom
