#pragma once
// Staging databases of a time series whose steps the ranks share
// (series_capture.cpp, `series: {ranks: steps}`): each rank writes the
// whole steps it captures into <database>.staging/rank-<k>, as the batch
// workflow's ranks do (staging.h, docs/scale-out.md), and the lead adopts
// them into the one database at the end. The writer keeps rows sorted by
// their values, so the database is the one a single process writes whatever
// rank captured which step. Every function here runs on the lead alone.
#include <darkroom/workflows/capture.h>

#include <set>
#include <string>

namespace darkroom::workflows::detail {

// <database>.staging/rank-<rank>, absolute.
std::string seriesStagingDatabase(const SceneCapture& r, int rank);

// Before any step: refuses an existing database without --overwrite or
// --resume, and a staging folder Darkroom did not make; a resume first
// adopts what an interrupted run over ranks left staged, an overwrite
// drops it, and anything else is refused while entries are staged. Leaves
// an empty staging folder with its marker. Throws InputError.
void prepareSeriesStaging(const SceneCapture& r);

// The entry names (cinemaEntryName, in the database's column order) a
// resume keeps: complete rows of the database; empty without --resume.
std::set<std::string> seriesEntriesKept(const SceneCapture& r);

// After every rank finished its steps: the staged entries adopted into the
// database (a resume keeps the rows it holds), which is finished; the
// staging folder removed. Throws darkroom::Error.
void mergeSeriesStaging(const SceneCapture& r);

}  // namespace darkroom::workflows::detail
