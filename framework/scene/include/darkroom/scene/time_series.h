#pragma once
// Time series in a scene file: an object whose `file` is a glob pattern
// (`steps/step_*.vtu`), a ParaView `.pvd` collection or a Cinema database
// whose FILE column lists meshes or volumes (docs/scene-format.md, "Time
// series"). Scanning a scene lists its steps — the values of the database
// columns that stand for each step and the file every series object draws
// there — without reading any mesh; `darkroom capture` then loads one step at
// a time (SceneLoadOptions::stepFiles).
#include <darkroom/export.h>
#include <darkroom/data/cinema/writer.h>

#include <cstddef>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace darkroom {

// One step: its column values (in SceneSeries::columns order) and, per
// series object (its index in the scene file's `objects` list), the file it
// draws at this step. Static objects are not listed: they appear in every step.
struct SeriesStep {
    std::vector<CinemaValue> values;
    std::map<std::size_t, std::string> files;
    std::string label;  // "time=0.5", for progress and messages
};

// How `mpirun -np N darkroom capture` shares a series (`series: {ranks: ...}`):
// Steps, each rank captures whole steps of its own into a staging database
// merged at the end; Partition, every rank holds a part of every step (for
// steps too big for one rank); Auto, Steps when there are at least as many
// steps as ranks, else Partition.
enum class SeriesRanks { Auto, Steps, Partition };

struct SceneSeries {
    // `time`, or the parameter columns of a series that is a Cinema database.
    std::vector<std::string> columns;
    std::vector<SeriesStep> steps;  // in time order; empty: the scene has no series
    // `cameras: {framing: step}`: each step framed on its own bounds. By
    // default (`framing: series`) cameras are framed once, on the union of
    // every step's bounds, so they stay put across the series.
    bool framePerStep = false;
    SeriesRanks ranks = SeriesRanks::Auto;
    // Every file the series name (each once), for what a resume compares.
    std::vector<std::string> files;
};

// Whether an object's `file:` value names a series rather than one mesh: a
// glob pattern (* ? [), a `.pvd`, or a folder (a Cinema database).
DARKROOM_API bool isSeriesFile(const std::string& value, const std::string& baseDir);

// The steps of a scene file's series. Several series objects are matched by
// time value and must hold the same times. Throws InputError naming
// scene.yaml:line:column, or the .pvd / data.csv and line, and what was
// expected: a glob that matches nothing, a .pvd that is not a ParaView
// collection or names a missing file, a database without a FILE column of
// meshes, series whose times differ.
DARKROOM_API SceneSeries scanSceneSeries(const std::string& sceneFile);

}  // namespace darkroom
