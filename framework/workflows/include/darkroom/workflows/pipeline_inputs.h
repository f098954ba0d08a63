#pragma once
// What `darkroom validate` checks of the files a pipeline names, short of
// running it (docs/cli.md, "What validate checks").
#include <darkroom/export.h>
#include <darkroom/core/graph.h>
#include <darkroom/diagnostics.h>

#include <string>

namespace darkroom::workflows {

// One diagnostic per problem, at the node's line in `pipelinePath`, naming
// the node, the input and what was expected. Relative paths resolve against
// the pipeline's folder, as `darkroom run` resolves them.
// - A colour map must be a preset (else the nearest preset is suggested) or
//   an existing file.
// - A Path input must name an existing file or folder, unless a node of the
//   pipeline writes there (an output path that is, holds or lies inside it).
// - The database of an entry reader (CinemaReader) must open: a folder with
//   a data.csv, or a .csv, that parses; the tolerant reader's notes come as
//   warnings.
// Inputs fed by an edge get their value when the pipeline runs and are not
// looked at. Nothing else is read: no image, mesh, scene, product or
// colour-map JSON is decoded, and nothing is written.
DARKROOM_API Diagnostics checkPipelineInputs(const Graph& g, const std::string& pipelinePath);

}  // namespace darkroom::workflows
