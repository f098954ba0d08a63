// A series named by a glob pattern: one file per step, timed by the number
// in its name (step_0007.vtu) or by the scene's `time:` list.
#include "series_sources.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <glob.h>

namespace darkroom::series {

std::optional<double> timeInName(const std::string& fileName) {
    const std::string stem = std::filesystem::path(fileName).stem().string();
    auto end = stem.find_last_of("0123456789");
    if (end == std::string::npos) return std::nullopt;
    auto begin = end;
    while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    // A decimal part: "t0.25" is 0.25, not 25.
    if (begin >= 2 && stem[begin - 1] == '.' && std::isdigit(static_cast<unsigned char>(stem[begin - 2]))) {
        --begin;
        while (begin > 0 && std::isdigit(static_cast<unsigned char>(stem[begin - 1]))) --begin;
    }
    return std::stod(stem.substr(begin, end + 1 - begin));
}

namespace {

std::vector<std::string> matches(const std::string& pattern) {
    glob_t g{};
    const int rc = ::glob(pattern.c_str(), GLOB_ERR, nullptr, &g);
    std::vector<std::string> files;
    if (rc == 0)
        for (std::size_t i = 0; i < g.gl_pathc; ++i) files.emplace_back(g.gl_pathv[i]);
    globfree(&g);
    if (rc != 0 && rc != GLOB_NOMATCH) throw Error("'" + pattern + "': cannot list the folder the pattern names");
    // Folders are not steps (a pattern like steps/* would also match them).
    files.erase(std::remove_if(files.begin(), files.end(),
                               [](const std::string& f) { return std::filesystem::is_directory(f); }),
                files.end());
    return files;
}

}  // namespace

ObjectSeries globSeries(const std::string& pattern, const std::string& baseDir,
                        const std::optional<std::vector<double>>& times) {
    std::filesystem::path p = pattern;
    if (p.is_relative()) p = std::filesystem::path(baseDir) / p;
    const std::string full = p.lexically_normal().string();
    std::vector<std::string> files = matches(full);
    if (files.empty())
        throw Error("no file matches '" + full + "'; expected the pattern to match one file per time step " +
                    "(e.g. step_*.vtu, relative to the scene file)");
    std::sort(files.begin(), files.end());
    ObjectSeries out;
    if (times) {
        if (times->size() != files.size())
            throw Error("'time' lists " + std::to_string(times->size()) + " values but '" + full + "' matches " +
                        std::to_string(files.size()) + " files; expected one value per file (in name order)");
        for (std::size_t i = 0; i < files.size(); ++i) out.items.push_back({(*times)[i], {}, files[i]});
    } else {
        for (const std::string& f : files) {
            const std::optional<double> t = timeInName(f);
            if (!t)
                throw Error("'" + f + "' (matched by '" + full + "') has no number in its name to time it by; " +
                            "expected names like step_0007.vtu, or a 'time' list");
            out.items.push_back({t, {}, f});
        }
    }
    std::stable_sort(out.items.begin(), out.items.end(),
                     [](const SeriesItem& a, const SeriesItem& b) { return *a.time < *b.time; });
    for (std::size_t i = 1; i < out.items.size(); ++i)
        if (*out.items[i].time == *out.items[i - 1].time)
            throw Error("'" + out.items[i - 1].file + "' and '" + out.items[i].file + "' have the same time " +
                        CinemaValue(*out.items[i].time).str() + "; expected one file per time step");
    for (const SeriesItem& item : out.items) requireRegularFile(item.file, "time step");
    return out;
}

}  // namespace darkroom::series
