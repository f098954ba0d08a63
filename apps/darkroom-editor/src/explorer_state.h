#pragma once
// The explorer's selection as it is saved with the pipeline: a key
// `explore:` in the CinemaReader node the explorer drives, beside `ui:`.
// The pipeline loader keeps keys it does not interpret verbatim, and the
// runner ignores them, so the file still runs with `darkroom run`:
//
//   explore: {brushes: [["phi", 0, 90], ["kind", "a", "b"]], sort: "time", descending: false, show: product}
//
// A numeric brush is the range of values; a text brush its first and last
// category. The picked row is the reader's own `entry`.
#include "explorer_model.h"

#include <darkroom/core/graph.h>

#include <string>
#include <vector>

namespace editor {

struct ExplorerState {
    struct AxisBrush {
        std::string axis;
        std::string low, high;  // numbers (shortest form) or category names
        bool operator==(const AxisBrush&) const = default;
    };
    std::vector<AxisBrush> brushes;
    std::string sort;  // axis name; empty: database order
    bool descending = false;
    bool pipeline = false;  // the grid shows the pipeline's output, not the raw products
    bool operator==(const ExplorerState&) const = default;
};

// The node key the state is saved under.
inline constexpr const char* kExploreKey = "explore";

// One line of YAML flow text. Names and values are double-quoted, with
// '%', '"', '\' and control characters percent-encoded, so the text
// survives the loader's verbatim round trip of unknown keys unchanged.
std::string toYaml(const ExplorerState& s);
// Throws darkroom::Error saying what is wrong with the text.
ExplorerState parseExplorerState(const std::string& yaml);

// The node's saved state text, "" when it has none; setting "" removes it.
std::string explorerText(const darkroom::Node& n);
void setExplorerText(darkroom::Graph& g, const std::string& node, const std::string& text);

ExplorerState captureState(const ExplorerModel& m, bool pipeline);
// Brushes on axes or categories the database lacks are left out, each
// with a line in `problems`.
void applyState(ExplorerModel& m, const ExplorerState& s, std::vector<std::string>* problems);

}  // namespace editor
