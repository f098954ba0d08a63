#pragma once
// The reduced-resolution copy of a graph that the editor evaluates while a
// value is being dragged. Every image output of a source node (a node that
// reads no image: CinemaReader, ImageReader, Capture, ...) passes through a
// Resize node at 1/2^level of its size before anything reads it, so
//  - the sources and their downsampled copies stay cached between drag steps
//    (the inserted nodes keep one version per level), and only what lies
//    downstream of the edit runs again, on 4^level times fewer pixels;
//  - radii in world units or image-height fractions keep their meaning:
//    the camera travels with the buffer and Resize updates its resolution.
// Sizes given in pixels (blur half-widths, outline widths) cover more of the
// picture in a preview; the settled frame at full resolution is exact.
#include <darkroom/core/graph.h>

#include <string>

namespace editor {

// Name of the Resize node inserted after source.port ("preview-surface-image").
std::string previewNodeName(const std::string& source, const std::string& port);

// The preview graph at 1/2^level (level >= 1). Nodes of `graph` keep their
// names and versions; throws darkroom::Error when the registry lacks Resize.
darkroom::Graph makePreviewGraph(const darkroom::Graph& graph, int level);

}  // namespace editor
