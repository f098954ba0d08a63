#pragma once
// What the explorer's grid shows for an entry: its raw product, read by the
// pipeline's CinemaReader exactly as the browser reads it (cinema_entries.h),
// or what the pipeline makes of it: the graph with its CinemaReader set to
// the entry, the shown node's output evaluated at reduced resolution
// (preview_graph.h) on the worker's own evaluator.
#include "thumbnail_cache.h"

#include <darkroom/core/graph.h>

#include <memory>
#include <string>
#include <vector>

namespace darkroom { class Registry; }

namespace editor {

// `rows[item]`: CinemaReader's `entry` for each item.
ThumbnailSourceFactory productThumbnails(const darkroom::Registry& registry, std::string database,
                                         std::vector<std::size_t> rows);

struct PipelineThumbnails {
    std::shared_ptr<const darkroom::Graph> graph;
    std::string reader;      // the CinemaReader node the entries go to
    std::string node, port;  // the image output shown
    std::string inputBase;   // the pipeline's folder
    int level = -1;          // sources at 1/2^level; -1: chosen from the first entry's product
};
ThumbnailSourceFactory pipelineThumbnails(PipelineThumbnails spec, std::vector<std::size_t> rows);

// The preview level that brings a `width`-pixel source down to about twice
// the thumbnail size (0: already small).
int thumbnailLevel(int width, int thumbnailSize);

}  // namespace editor
