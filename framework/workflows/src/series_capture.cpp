// `darkroom capture` of a scene whose objects include time series
// (darkroom/scene/time_series.h): ONE database, rows = steps x cameras, the
// series' columns (`time`, or a source database's) before the cameras'.
//
// Steps are loaded one at a time (whole, or this process's part of it when
// the ranks partition each step; series_ranks.cpp when they share the
// steps instead), captured through the same loop as a static scene
// (captureEntries), and dropped before the next, so memory is bounded by one
// step. Cameras stay put: unless the scene asks for `framing: step`, a first
// pass loads each step once (the processes sharing the steps) for the union
// of their bounds, on which every step is then framed — a movie over time
// that reframes each step zooms in and out as the data grows and shrinks.
#include "series_steps.h"

#include <darkroom/data/cinema/naming.h>

#include <darkroom/error.h>
#include <darkroom/core/registry.h>
#include <darkroom/core/run_filter.h>

#include <algorithm>
#include <filesystem>
#include <cstdio>
#include <sstream>

namespace darkroom::workflows::detail {

namespace {

SceneLoadOptions stepOptions(const SeriesStep& step, const std::optional<Bounds>& framing) {
    SceneLoadOptions o;
    o.stepFiles = step.files;
    o.framing = framing;
    return o;
}

Bounds unite(Bounds a, const Bounds& b) {
    if (b.empty()) return a;
    a.lo = {std::min(a.lo.x, b.lo.x), std::min(a.lo.y, b.lo.y), std::min(a.lo.z, b.lo.z)};
    a.hi = {std::max(a.hi.x, b.hi.x), std::max(a.hi.y, b.hi.y), std::max(a.hi.z, b.hi.z)};
    return a;
}

// The first pass: the union of every step's bounds. Each process loads its
// block of steps whole, one at a time, keeping only their bounds.
Bounds seriesBounds(const SceneCapture& r, const SceneSeries& series, ProcessGroup& group) {
    Bounds mine;
    std::string error;
    const auto [first, last] = blockOf(series.steps.size(), group.rank(), group.size());
    try {
        for (std::size_t s = first; s < last; ++s) {
            if (group.lead() && r.progress)
                r.progress(0.0, "bounds of " + series.steps[s].label);
            mine = unite(mine, loadSceneFile(r.scene, stepOptions(series.steps[s], std::nullopt)).scene->bounds());
        }
    } catch (const Error& e) {
        error = e.what();
    }
    if (const std::string e = group.agreedError(error); !e.empty()) throw InputError(e);
    char text[160] = "";
    if (!mine.empty())
        std::snprintf(text, sizeof text, "%.17g %.17g %.17g %.17g %.17g %.17g", mine.lo.x, mine.lo.y, mine.lo.z,
                      mine.hi.x, mine.hi.y, mine.hi.z);
    Bounds all;
    for (const std::string& t : group.allGather(text)) {
        std::istringstream in(t);
        Bounds b;
        if (in >> b.lo.x >> b.lo.y >> b.lo.z >> b.hi.x >> b.hi.y >> b.hi.z) all = unite(all, b);
    }
    return all;
}

// The database's rows of one step: the step's column values, then the camera's.
std::vector<CaptureEntry> stepEntries(const SceneSeries& series, const SeriesStep& step,
                                      const SceneDescription& scene) {
    std::vector<CaptureEntry> entries = captureEntriesOf(scene);
    for (CaptureEntry& e : entries) {
        for (std::size_t c = 0; c < series.columns.size(); ++c) e.parameters.emplace(series.columns[c], step.values[c]);
        e.label = step.label + " " + e.label;
    }
    return entries;
}

// The name of an entry's files, in the database's column order (the
// series' columns, then the cameras'), as a resume lists what it keeps.
std::string entryName(const CinemaParameters& parameters, const SceneSeries& series) {
    std::vector<std::pair<std::string, std::string>> named;
    for (const std::string& c : series.columns) named.emplace_back(c, parameters.at(c).str());
    for (const auto& [k, v] : parameters)
        if (std::find(series.columns.begin(), series.columns.end(), k) == series.columns.end())
            named.emplace_back(k, v.str());
    return cinemaEntryName(named);
}

// The rows of a step a resume keeps: in the database open on the lead, or
// among `kept` (the database's, when the ranks share the steps).
std::size_t keptRows(const std::vector<CaptureEntry>& rows, const SeriesOutput& out, const SceneSeries& series) {
    std::size_t kept = 0;
    for (const CaptureEntry& e : rows)
        if ((out.writer && out.writer->hasEntry(e.parameters)) || out.kept.count(entryName(e.parameters, series)))
            ++kept;
    return kept;
}

// Whether the database holds every row of a step, agreed.
bool stepComplete(const SeriesOutput& out, const SceneSeries& series, const SeriesStep& step, ProcessGroup& group) {
    std::vector<CaptureEntry> rows = out.cameraRows;
    for (CaptureEntry& e : rows)
        for (std::size_t c = 0; c < series.columns.size(); ++c)
            e.parameters.insert_or_assign(series.columns[c], step.values[c]);
    std::string complete = group.lead() && keptRows(rows, out, series) == rows.size() ? "1" : "0";
    group.broadcast(complete);
    return complete == "1";
}

// Refuses a series column the cameras also write (a database column `phi`).
void checkColumns(const SceneSeries& series, const SceneDescription& scene) {
    for (const auto& [name, value] : scene.cameras.front().parameters)
        if (std::find(series.columns.begin(), series.columns.end(), name) != series.columns.end())
            throw InputError(scene.path + ": the time series' column '" + name +
                             "' is also a camera column; expected the series' columns to differ from the cameras'");
}

// The origin a resume compares: the first step's scene, reading every file
// of every step. Whichever step a process loaded first, its files are named
// as the first step's, so that every rank records (and a resume compares)
// the origin one process records.
SceneDescription seriesOrigin(SceneDescription scene, const SceneSeries& series, const SeriesStep& step) {
    scene.scene.reset();
    for (std::string& f : scene.inputFiles)
        for (const auto& [object, file] : step.files)
            if (f == file) f = series.steps.front().files.at(object);
    for (const std::string& f : series.files)
        if (std::find(scene.inputFiles.begin(), scene.inputFiles.end(), f) == scene.inputFiles.end())
            scene.inputFiles.push_back(f);
    return scene;
}

// The database (or this rank's staging database, made afresh), opened at
// the first entry captured.
CinemaWriter& openOutput(const SceneCapture& r, const SceneSeries& series, const SeriesStep& step,
                         const SceneDescription& scene, SeriesOutput& out) {
    if (out.writer) return *out.writer;
    std::map<std::string, std::string> attachments;
    CinemaWriterOptions wo = writerOptions(r, seriesOrigin(scene, series, step), attachments);
    if (out.staging) {
        wo.overwrite = true;
        wo.resume = false;
    }
    std::vector<std::string> columns = series.columns;
    for (const auto& [k, v] : scene.cameras.front().parameters) columns.push_back(k);
    out.writer = std::make_unique<CinemaWriter>(out.path, columns, wo);
    return *out.writer;
}

// The rows of a step still to capture: those a resume keeps (the shared
// steps' `kept`) left out and counted.
std::vector<CaptureEntry> rowsToCapture(std::vector<CaptureEntry> rows, const SeriesOutput& out,
                                        const SceneSeries& series, std::size_t& kept) {
    if (out.kept.empty()) return rows;
    const std::size_t before = rows.size();
    rows.erase(std::remove_if(rows.begin(), rows.end(),
                              [&](const CaptureEntry& e) { return out.kept.count(entryName(e.parameters, series)); }),
               rows.end());
    kept = before - rows.size();
    return rows;
}

// Loads step `s` (this process's part, or the whole step when it captures
// it alone), captures its cameras through captureEntries and drops it again.
CaptureSummary captureStep(const SceneCapture& r, const SceneSeries& series, std::size_t s,
                           const std::optional<Bounds>& framing, const Registry& registry, Context& ctx,
                           ProcessGroup& group, SeriesOutput& out) {
    const SeriesStep& step = series.steps[s];
    if (out.reportProgress && r.progress) r.progress(double(s) / double(series.steps.size()), "loading " + step.label);
    const PartitionedScene part = loadScene(r.scene, group, stepOptions(step, framing));
    const SceneDescription& scene = part.description;
    if (r.warn)
        for (const auto& w : scene.warnings) r.warn(step.label + ": " + w);
    if (scene.cameras.empty()) throw InputError(r.scene + ": the scene has no cameras");
    checkColumns(series, scene);

    std::string error;
    std::unique_ptr<CaptureBackend> backend;
    CaptureSettings settings;
    try {
        backend = registry.createBackend(scene.backend);
        backend->setScene(scene.scene);
        CinemaWriterOptions scratch;
        settings.attachments = pointListAttachments(scene, scratch);
    } catch (const Error& e) {
        error = e.what();
    }
    if (const std::string e = group.agreedError(error); !e.empty()) throw InputError(e);

    settings.openDatabase = [&]() -> CinemaWriter& { return openOutput(r, series, step, scene, out); };
    settings.request = scene.request;
    settings.primitiveOffsets = part.primitiveOffset;
    settings.cancel = r.cancel;
    if (r.progress && out.reportProgress)
        settings.progress = [&](double f, const std::string& label) {
            r.progress((double(s) + f) / double(series.steps.size()), label);
        };
    const RenderFn render = [&](const Camera& camera, const CaptureRequest& request) {
        return backend->render(camera, request, ctx);
    };
    out.cameraRows = captureEntriesOf(scene);
    CaptureSummary summary;
    const std::vector<CaptureEntry> rows = rowsToCapture(stepEntries(series, step, scene), out, series, summary.kept);
    if (rows.empty()) return summary;
    const std::size_t kept = summary.kept;
    summary = captureEntries(rows, render, group, settings);
    summary.kept += kept;
    out.captured.push_back(step.label);
    return summary;
}

}  // namespace

CaptureSummary captureSteps(const SceneCapture& r, const SceneSeries& series, const std::optional<Bounds>& framing,
                            const Registry& registry, Context& ctx, ProcessGroup& group, const NextStep& next,
                            SeriesOutput& out) {
    CaptureSummary total;
    while (const std::optional<std::size_t> s = next()) {
        // Once a step was loaded, a resume skips the steps the database holds whole without loading them.
        if (!out.cameraRows.empty() && stepComplete(out, series, series.steps[*s], group)) {
            total.kept += out.cameraRows.size();
            continue;
        }
        const CaptureSummary summary = captureStep(r, series, *s, framing, registry, ctx, group, out);
        total.rendered += summary.rendered;
        total.kept += summary.kept;
        total.renderSeconds += summary.renderSeconds;
        total.compositeSeconds += summary.compositeSeconds;
        total.writeSeconds += summary.writeSeconds;
    }
    return total;
}

void checkResumedOrigin(const SceneCapture& r, const SceneSeries& series, const std::optional<Bounds>& framing) {
    if (!r.resume || !std::filesystem::exists(std::filesystem::path(r.output) / "data.csv")) return;
    const SeriesStep& first = series.steps.front();
    const SceneDescription scene = loadSceneFile(r.scene, stepOptions(first, framing));
    std::map<std::string, std::string> attachments;
    CinemaWriter::check(r.output, writerOptions(r, seriesOrigin(scene, series, first), attachments));
}

bool shareSteps(const SceneSeries& series, const ProcessGroup& group) {
    if (group.size() == 1) return false;
    switch (series.ranks) {
        case SeriesRanks::Steps: return true;
        case SeriesRanks::Partition: return false;
        case SeriesRanks::Auto: break;
    }
    // Fewer steps than ranks would leave ranks idle: they share each step's primitives instead.
    return series.steps.size() >= std::size_t(group.size());
}

CaptureSummary captureSceneSeries(const SceneCapture& r, const SceneSeries& series, const Registry& registry,
                                  ProcessGroup& group) {
    const std::optional<Bounds> framing =
        series.framePerStep ? std::nullopt : std::optional<Bounds>(seriesBounds(r, series, group));
    FilterRunOptions ro;
    ro.threads = threadsPerProcess(r, group);
    ro.registry = &registry;
    const std::unique_ptr<Context> ctx = makeStandaloneContext(ro, "capture");
    if (shareSteps(series, group)) return captureSharedSteps(r, series, framing, registry, *ctx, group);

    // Every process takes part in every step, in order.
    SeriesOutput out;
    out.path = r.output;
    out.reportProgress = group.lead();
    std::size_t s = 0;
    const NextStep next = [&]() -> std::optional<std::size_t> {
        if (s == series.steps.size()) return std::nullopt;
        return s++;
    };
    const CaptureSummary total = captureSteps(r, series, framing, registry, *ctx, group, next, out);
    if (out.writer) out.writer->finish();
    return total;
}

}  // namespace darkroom::workflows::detail
