// A time series over `mpirun -np N darkroom capture` with the steps shared
// (series_steps.h): each rank takes whole steps from a work queue and
// captures them alone — no compositing, memory bounded by one step per
// rank — into its staging database; the lead merges them at the end into
// the one database a single process writes (series_staging.h).
#include "series_staging.h"
#include "series_steps.h"

#include <darkroom/error.h>

#include <algorithm>
#include <sstream>

namespace darkroom::workflows::detail {

namespace {

// What a rank's failure was, so that every rank throws the same kind.
enum class Failure : char { None = '-', Input = 'I', Runtime = 'E', Cancelled = 'C' };

// Before any step, on the lead: the database and the staging folder checked
// and prepared; the entries a resume keeps, on every rank.
std::set<std::string> prepare(const SceneCapture& r, const SceneSeries& series, const std::optional<Bounds>& framing,
                              ProcessGroup& group) {
    std::string error, kept;
    if (group.lead()) {
        try {
            prepareSeriesStaging(r);
            checkResumedOrigin(r, series, framing);
            for (const std::string& name : seriesEntriesKept(r)) kept += name + "\n";
        } catch (const Error& e) {
            error = e.what();
        }
    }
    if (const std::string e = group.agreedError(error); !e.empty()) throw InputError(e);
    group.broadcast(kept);
    std::set<std::string> names;
    std::istringstream in(kept);
    for (std::string line; std::getline(in, line);) names.insert(line);
    return names;
}

// This rank's steps from the work queue, captured alone; its staging
// database finished. A failure stops the other ranks' taking.
CaptureSummary captureMine(const SceneCapture& r, const SceneSeries& series, const std::optional<Bounds>& framing,
                           const Registry& registry, Context& ctx, ProcessGroup& group, SeriesOutput& out,
                           Failure& failure, std::string& error) {
    SingleProcess alone;
    CaptureSummary mine;
    const std::unique_ptr<WorkQueue> queue = group.workQueue(series.steps.size());
    bool taken = false;
    const NextStep next = [&]() -> std::optional<std::size_t> {
        if (taken) queue->finished();
        const std::optional<std::size_t> s = queue->next();
        taken = s.has_value();
        return s;
    };
    try {
        mine = captureSteps(r, series, framing, registry, ctx, alone, next, out);
        if (out.writer) out.writer->finish();  // before the lead reads it
    } catch (const Cancelled&) {
        failure = Failure::Cancelled;
        error = "darkroom: capture cancelled";
    } catch (const InputError& e) {
        failure = Failure::Input;
        error = e.what();
    } catch (const Error& e) {
        failure = Failure::Runtime;
        error = e.what();
    }
    if (failure != Failure::None) queue->failed();
    return mine;
}

// Every rank's counts summed (times: the slowest rank's); the steps each captured.
CaptureSummary gathered(const CaptureSummary& mine, const SeriesOutput& out, ProcessGroup& group) {
    std::ostringstream text;
    text.precision(17);
    text << mine.rendered << " " << mine.kept << " " << mine.renderSeconds << " " << mine.writeSeconds;
    for (const std::string& label : out.captured) text << "\n" << label;
    CaptureSummary all;
    const std::vector<std::string> ranks = group.allGather(text.str());
    for (std::size_t k = 0; k < ranks.size(); ++k) {
        std::istringstream in(ranks[k]);
        std::size_t rendered = 0, kept = 0;
        double render = 0, write = 0;
        in >> rendered >> kept >> render >> write;
        all.rendered += rendered;
        all.kept += kept;
        all.renderSeconds = std::max(all.renderSeconds, render);
        all.writeSeconds = std::max(all.writeSeconds, write);
        std::string steps, line;
        std::getline(in, line);
        while (std::getline(in, line)) steps += (steps.empty() ? "" : ", ") + line;
        all.stepsPerRank.push_back(steps);
    }
    return all;
}

}  // namespace

CaptureSummary captureSharedSteps(const SceneCapture& r, const SceneSeries& series,
                                  const std::optional<Bounds>& framing, const Registry& registry, Context& ctx,
                                  ProcessGroup& group) {
    SeriesOutput out;
    out.kept = prepare(r, series, framing, group);
    out.path = seriesStagingDatabase(r, group.rank());
    out.staging = true;
    out.reportProgress = group.lead();

    Failure failure = Failure::None;
    std::string error;
    const CaptureSummary mine = captureMine(r, series, framing, registry, ctx, group, out, failure, error);
    out.writer.reset();
    const std::vector<std::string> kinds = group.allGather(std::string(1, char(failure)));
    if (const std::string e = group.agreedError(error); !e.empty()) {
        const auto any = [&](Failure f) { return std::count(kinds.begin(), kinds.end(), std::string(1, char(f))) > 0; };
        if (any(Failure::Cancelled)) throw Cancelled();
        if (any(Failure::Input)) throw InputError(e);
        throw Error(e);
    }
    CaptureSummary all = gathered(mine, out, group);
    std::string mergeError;
    if (group.lead()) {
        try {
            mergeSeriesStaging(r);
        } catch (const Error& e) {
            mergeError = e.what();
        }
    }
    if (const std::string e = group.agreedError(mergeError); !e.empty()) throw Error(e);
    return all;
}

}  // namespace darkroom::workflows::detail
