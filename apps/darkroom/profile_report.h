#pragma once
// `darkroom run --profile`: one table per evaluation on stderr, a row per node
// in the order they finished: its time, whether it ran or came from the cache,
// and the bytes of new planes it allocated.
#include <darkroom/core/evaluator.h>

#include <string>
#include <vector>

namespace darkroom::cli {

void printProfile(const std::string& title, const std::vector<NodeProfile>& nodes, double wallSeconds);

}  // namespace darkroom::cli
