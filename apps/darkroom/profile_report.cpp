#include "profile_report.h"

#include <fmt/core.h>

#include <algorithm>
#include <cstdio>

namespace darkroom::cli {

void printProfile(const std::string& title, const std::vector<NodeProfile>& nodes, double wallSeconds) {
    std::size_t nameWidth = 4, typeWidth = 4;
    for (const auto& n : nodes) {
        nameWidth = std::max(nameWidth, n.node.size());
        typeWidth = std::max(typeWidth, n.type.size());
    }
    std::string out = fmt::format("profile: {} ({:.1f} ms)\n", title, wallSeconds * 1e3);
    out += fmt::format("  {:<{}}  {:<{}}  {:<11}  {:>9}  {:>9}  {}\n", "node", nameWidth, "type", typeWidth,
                       "status", "ms", "MB new", "why it ran");
    std::size_t ran = 0, bytes = 0;
    double seconds = 0;
    for (const auto& n : nodes) {
        out += fmt::format("  {:<{}}  {:<{}}  {:<11}  {:>9.2f}  {:>9.1f}  {}\n", n.node, nameWidth, n.type, typeWidth,
                           toString(n.status), n.seconds * 1e3, double(n.bytesAllocated) / (1 << 20),
                           n.status == NodeProfile::Status::Ran ? n.reason : "");
        ran += n.status == NodeProfile::Status::Ran;
        seconds += n.seconds;
        bytes += n.bytesAllocated;
    }
    out += fmt::format("  {} of {} nodes ran, {:.1f} ms in nodes, {:.1f} MB of new planes\n", ran, nodes.size(),
                       seconds * 1e3, double(bytes) / (1 << 20));
    std::fputs(out.c_str(), stderr);
}

}  // namespace darkroom::cli
