#pragma once
// The storage half of bench_layers: a layered G-buffer (darkroom/layers.h)
// written and read back as the flat multi-channel EXR the framework writes,
// and as an OpenEXR deep image through OpenImageIO.
#include <darkroom/buffer.h>

#include <string>
#include <vector>

namespace darkroom::bench {

struct StorageFigure {
    std::string layout;  // "flat zip", "flat zips", "deep zips"
    std::size_t bytes = 0;
    double writeSeconds = 0, readSeconds = 0;  // best of the repetitions, wall clock
    double writeCpu = 0, readCpu = 0;          // the same in CPU seconds of the process (all threads)
};

// Crossings per pixel, averaged (finite depths over all layers).
double meanCrossings(const Buffer& g);

// Writes `g` into `dir` in each layout `reps` times, reads it back as many
// times (the deep file into the flat layout, as a reader of deep files would
// have to give the graph), checks the values survive, and reports.
std::vector<StorageFigure> measureStorage(const Buffer& g, const std::string& dir, int reps);

}  // namespace darkroom::bench
