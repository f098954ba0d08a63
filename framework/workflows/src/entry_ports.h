#pragma once
// How the batch workflow finds the nodes it drives: by the kind of their
// ports (the SDK's PortType), not by their names or types.
//  - An entry reader (CinemaReader) has a Row output, its database as a Path
//    input, and an Int input `entry`: the row it reads, which the batch sets.
//  - A database writer (CinemaWriter) has a Row input fed by an edge and an
//    OutputPath input, the database it writes; it names its entries itself.
#include <darkroom/core/graph.h>

#include <string>

namespace darkroom::workflows {

inline constexpr const char* kEntryPort = "entry";
// An entry reader's optional String input that the batch sets to its
// --where: the rows the run covers (CinemaReader passes it on as metadata).
inline constexpr const char* kSelectionPort = "selection";

// The database input (the first Path input) of an entry reader; nullptr when
// `n` is not one.
const PortSpec* entryReaderDatabase(const Graph& g, const Node& n);

// Whether an input of `n` chooses which entry an entry reader reads: `entry`,
// `parameters`, the choice by values that `entry` overrides, and
// `selection`, the rows of the run. The batch sets them per run or entry;
// none says what a pipeline does.
bool choosesEntry(const Graph& g, const Node& n, const PortSpec& input);

// Whether an edge feeds one of the node's Row inputs.
bool isFedARow(const Graph& g, const Node& n);

// The output-path input (PortType::OutputPath) of a database writer, its
// database; nullptr when `n` has none.
const PortSpec* writerDatabase(const Graph& g, const Node& n);

// Whether `n` is a database writer (fed a row) whose database comes through
// an edge: it cannot be given a staging database per rank or lane.
bool writesADatabaseThroughAnEdge(const Graph& g, const Node& n);

}  // namespace darkroom::workflows
