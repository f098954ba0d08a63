#pragma once
// The steps of one series object, by kind of source: a glob pattern, a
// ParaView .pvd collection, a Cinema database (docs/scene-format.md, "Time
// series"). Each lists its files in time order; none reads a mesh.
#include <darkroom/data/cinema/writer.h>

#include <optional>
#include <string>
#include <vector>

namespace darkroom::series {

struct SeriesItem {
    std::optional<double> time;        // what series are matched by; none: a database without a time column
    std::vector<CinemaValue> values;   // a database's parameter cells (its `columns`)
    std::string file;
};

struct ObjectSeries {
    std::vector<std::string> columns;  // a database's parameter columns; empty for globs and .pvd
    std::vector<SeriesItem> items;
};

// The files matching `pattern` (relative to `baseDir` unless absolute), each
// timed by the last number in its name (step_0007.vtu: 7) or, when `times`
// is given, by those (one per file, files in name order). Throws Error
// naming the pattern when nothing matches, a name has no number, two files
// share a time, or `times` does not fit the files.
ObjectSeries globSeries(const std::string& pattern, const std::string& baseDir,
                        const std::optional<std::vector<double>>& times);

// The DataSets of a ParaView collection (<VTKFile type="Collection">
// <Collection><DataSet timestep="0.5" file="step_5.vtu"/>), files relative
// to the .pvd. Throws Error "file.pvd:LINE: ..." for bad XML, a missing or
// non-numeric timestep, a file that does not exist, two DataSets at one
// timestep.
ObjectSeries pvdSeries(const std::string& path);

// The rows of a Cinema database whose FILE column lists meshes or volumes:
// its parameter columns carried, timed by its `time` column (any case) if
// numeric. Throws Error naming data.csv for a database without one FILE
// column or with a product that does not exist.
ObjectSeries cinemaSeries(const std::string& path);

// The time value a file name carries: its last number (digits, with an
// optional decimal part): "step_0007.vtu" 7, "t0.25.vti" 0.25.
std::optional<double> timeInName(const std::string& fileName);

}  // namespace darkroom::series
