// Scanning a scene file for time series: which objects name one, their steps
// matched by time value, and how cameras frame them. Reads the YAML and the
// series' listings (folders, .pvd, data.csv), never a mesh.
#include "series_sources.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/core/yaml_guard.h>
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/scene/time_series.h>

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace darkroom {

bool isSeriesFile(const std::string& value, const std::string& baseDir) {
    if (value.find_first_of("*?[") != std::string::npos) return true;
    std::filesystem::path p = value;
    std::string ext = p.extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext == ".pvd") return true;
    if (p.is_relative()) p = std::filesystem::path(baseDir) / p;
    std::error_code ec;
    return std::filesystem::is_directory(p, ec);
}

namespace {

// A series object as scanned: its name and source position for messages.
struct Scanned {
    std::size_t index;
    std::string name, where;
    series::ObjectSeries steps;
};

std::string where(const std::string& source, const YAML::Node& n) {
    const YAML::Mark m = n.Mark();
    return source + ":" + std::to_string(m.line + 1) + ":" + std::to_string(m.column + 1);
}

std::optional<std::vector<double>> explicitTimes(const YAML::Node& t, const std::string& source) {
    if (!t) return std::nullopt;
    if (!t.IsSequence() || t.size() == 0)
        throw InputError(where(source, t) + ": 'time' must be a non-empty list of numbers, one per matched file");
    std::vector<double> out;
    for (const auto& x : t) {
        double v = 0;
        if (!x.IsScalar() || !mesh::parseDouble(x.Scalar(), v) || !std::isfinite(v))
            throw InputError(where(source, x) + ": 'time' values must be numbers");
        out.push_back(v);
    }
    return out;
}

// One object's steps, errors located at its `file:` (or `time:`).
Scanned scanObject(const YAML::Node& o, std::size_t index, const std::string& source, const std::string& baseDir) {
    const std::string value = o["file"].Scalar();
    Scanned s{index, o["name"] && o["name"].IsScalar() ? o["name"].Scalar()
                                                       : std::filesystem::path(value).stem().string(),
              where(source, o["file"]), {}};
    std::filesystem::path p = value;
    if (p.is_relative()) p = std::filesystem::path(baseDir) / p;
    const std::string full = p.lexically_normal().string();
    const bool glob = value.find_first_of("*?[") != std::string::npos;
    if (o["time"] && !glob)
        throw InputError(where(source, o["time"]) + ": 'time' only applies to a glob pattern; a .pvd or Cinema " +
                         "database carries its own times");
    try {
        if (glob) s.steps = series::globSeries(value, baseDir, explicitTimes(o["time"], source));
        else if (std::filesystem::is_directory(full)) s.steps = series::cinemaSeries(full);
        else s.steps = series::pvdSeries(full);
    } catch (const InputError& e) {
        throw InputError(s.where + ": object '" + s.name + "': " + e.what());
    } catch (const Error& e) {
        throw InputError(s.where + ": object '" + s.name + "': " + e.what());
    }
    return s;
}

std::string timeText(double t) { return CinemaValue(t).str(); }

// Every other series must hold exactly the leader's times.
void checkMatching(const Scanned& leader, const Scanned& other) {
    if (!leader.steps.items.front().time)
        throw InputError(leader.where + ": object '" + leader.name + "' is a database without a numeric time " +
                         "column, so object '" + other.name + "''s series cannot be matched to it by time value");
    std::set<double> mine, theirs;
    for (const auto& i : leader.steps.items) mine.insert(*i.time);
    for (const auto& i : other.steps.items) {
        if (!i.time)
            throw InputError(other.where + ": object '" + other.name + "' is a database without a numeric time " +
                             "column, so it cannot be matched to object '" + leader.name + "''s series by time value");
        theirs.insert(*i.time);
    }
    for (double t : mine)
        if (!theirs.count(t))
            throw InputError(other.where + ": object '" + other.name + "' has no step at time " + timeText(t) +
                             ", which object '" + leader.name + "' has; series are matched by time value and " +
                             "must hold the same times");
    for (double t : theirs)
        if (!mine.count(t))
            throw InputError(other.where + ": object '" + other.name + "' has a step at time " + timeText(t) +
                             ", which object '" + leader.name + "' lacks; series are matched by time value and " +
                             "must hold the same times");
}

// `cameras: {framing: series | step}`.
bool framePerStep(const YAML::Node& root, const std::string& source) {
    const YAML::Node c = root["cameras"];
    if (!c || !c.IsMap() || !c["framing"]) return false;
    const YAML::Node f = c["framing"];
    const std::string v = f.IsScalar() ? f.Scalar() : std::string();
    if (v != "series" && v != "step")
        throw InputError(where(source, f) + ": framing must be series (cameras framed once on the union of all " +
                         "steps' bounds, the default) or step (each step framed on its own bounds)");
    return v == "step";
}

// `series: {ranks: auto | steps | partition}`.
SeriesRanks seriesRanks(const YAML::Node& root, const std::string& source) {
    const YAML::Node s = root["series"];
    if (!s || !s.IsMap() || !s["ranks"]) return SeriesRanks::Auto;
    const YAML::Node f = s["ranks"];
    const std::string v = f.IsScalar() ? f.Scalar() : std::string();
    if (v == "steps") return SeriesRanks::Steps;
    if (v == "partition") return SeriesRanks::Partition;
    if (v != "auto")
        throw InputError(where(source, f) + ": ranks must be auto (the default: each rank captures whole steps " +
                         "when there are at least as many steps as ranks), steps (each rank captures whole steps) " +
                         "or partition (every rank holds a part of every step)");
    return SeriesRanks::Auto;
}

std::vector<SeriesStep> matchedSteps(const std::vector<Scanned>& all, const Scanned& leader,
                                     const std::vector<std::string>& columns) {
    std::vector<SeriesStep> steps;
    for (const series::SeriesItem& item : leader.steps.items) {
        SeriesStep step;
        step.values = leader.steps.columns.empty() ? std::vector<CinemaValue>{CinemaValue(*item.time)} : item.values;
        for (std::size_t c = 0; c < columns.size(); ++c)
            step.label += (c ? " " : "") + columns[c] + "=" + step.values[c].str();
        for (const Scanned& s : all) {
            if (&s == &leader) {
                step.files[s.index] = item.file;
                continue;
            }
            for (const auto& other : s.steps.items)
                if (*other.time == *item.time) step.files[s.index] = other.file;
        }
        steps.push_back(std::move(step));
    }
    return steps;
}

}  // namespace

SceneSeries scanSceneSeries(const std::string& sceneFile) {
    const std::string baseDir = std::filesystem::path(sceneFile).parent_path().string();
    YAML::Node root;
    try {
        root = yamlguard::load(readInputFile(sceneFile, "scene file"));
    } catch (const YAML::Exception& e) {
        throw InputError(sceneFile + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1) +
                         ": " + e.msg);
    }
    SceneSeries out;
    if (!root.IsMap() || !root["objects"] || !root["objects"].IsSequence()) return out;  // the loader says why
    std::vector<Scanned> all;
    const YAML::Node objects = root["objects"];
    for (std::size_t i = 0; i < objects.size(); ++i) {
        const YAML::Node o = objects[i];
        if (o.IsMap() && o["file"] && o["file"].IsScalar() && isSeriesFile(o["file"].Scalar(), baseDir))
            all.push_back(scanObject(o, i, sceneFile, baseDir));
    }
    if (all.empty()) return out;
    // A database's columns are carried, so it leads; else the first series, by `time`.
    auto leader = std::find_if(all.begin(), all.end(), [](const Scanned& s) { return !s.steps.columns.empty(); });
    if (leader == all.end()) leader = all.begin();
    for (const Scanned& s : all)
        if (&s != &*leader) checkMatching(*leader, s);
    out.columns = leader->steps.columns.empty() ? std::vector<std::string>{"time"} : leader->steps.columns;
    out.steps = matchedSteps(all, *leader, out.columns);
    out.framePerStep = framePerStep(root, sceneFile);
    out.ranks = seriesRanks(root, sceneFile);
    for (const Scanned& s : all)
        for (const auto& item : s.steps.items)
            if (std::find(out.files.begin(), out.files.end(), item.file) == out.files.end())
                out.files.push_back(item.file);
    return out;
}

}  // namespace darkroom
