#pragma once
// The step loop of a time series capture (series_capture.cpp) and the way
// the ranks share whole steps (series_ranks.cpp): one loop, fed the steps in
// order with every process capturing each together, or fed each rank's own
// steps from a work queue with the rank capturing them alone.
#include "scene_capture_steps.h"

#include <darkroom/core/run_filter.h>

#include <functional>
#include <optional>
#include <set>

namespace darkroom::workflows::detail {

// Where the steps' rows are written: the database, or this rank's staging
// database, opened at the first step captured (its columns and origin are
// known then).
struct SeriesOutput {
    std::string path;
    bool staging = false;          // a rank's staging database: created afresh
    bool reportProgress = false;   // this process reports progress (the lead)
    std::set<std::string> kept;    // entry names a resume keeps (shared steps: the database's)
    std::unique_ptr<CinemaWriter> writer;
    std::vector<CaptureEntry> cameraRows;  // the rows of a step without the series' columns
    std::vector<std::string> captured;     // labels of the steps captured here
};

// The next step to capture, none when done.
using NextStep = std::function<std::optional<std::size_t>()>;

// Captures each step `next` gives through captureEntries over `group`
// (every process, or this one alone), loading one step at a time and
// skipping the steps a resume holds whole.
CaptureSummary captureSteps(const SceneCapture& r, const SceneSeries& series, const std::optional<Bounds>& framing,
                            const Registry& registry, Context& ctx, ProcessGroup& group, const NextStep& next,
                            SeriesOutput& out);

// On a resume of an existing database: throws (darkroom::Error) when it was
// begun from another scene or other steps (its recorded origin), loading
// the first step for its description. The ranks sharing the steps write
// staging databases, so the lead checks this once before any step.
void checkResumedOrigin(const SceneCapture& r, const SceneSeries& series, const std::optional<Bounds>& framing);

// Whether the ranks of `group` share the steps (each captures whole steps)
// rather than every rank holding a part of every step: `series: {ranks:}`,
// by default when there are at least as many steps as ranks.
bool shareSteps(const SceneSeries& series, const ProcessGroup& group);

// The steps shared among the ranks: each captures whole steps from a work
// queue into its staging database, alone; the lead merges them into the
// one database at the end (series_staging.h).
CaptureSummary captureSharedSteps(const SceneCapture& r, const SceneSeries& series,
                                  const std::optional<Bounds>& framing, const Registry& registry, Context& ctx,
                                  ProcessGroup& group);

}  // namespace darkroom::workflows::detail
