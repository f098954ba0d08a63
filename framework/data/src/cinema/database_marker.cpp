#include "database_marker.h"

#include <darkroom/error.h>

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace darkroom::cinema_detail {

namespace {

constexpr const char* kVersionLine = "darkroom-database\t1";

// Tabs separate the fields and lines the items: neither may appear inside.
std::string field(std::string s) {
    for (char& c : s)
        if (c == '\t' || c == '\n' || c == '\r') c = ' ';
    return s;
}

std::vector<std::string> splitTabs(const std::string& line) {
    std::vector<std::string> out;
    std::size_t start = 0;
    for (;;) {
        const std::size_t tab = line.find('\t', start);
        out.push_back(line.substr(start, tab - start));
        if (tab == std::string::npos) return out;
        start = tab + 1;
    }
}

}  // namespace

std::string markerText(const std::vector<CinemaOriginItem>& origin) {
    std::string text =
        "# Darkroom created this Cinema database folder. --overwrite removes only the files its data.csv\n"
        "# lists and Darkroom's own, and only in a folder holding this file; --resume refuses to complete\n"
        "# it from anything other than what the origin lines record (docs/capture.md).\n";
    text += kVersionLine;
    text += "\n";
    for (const auto& item : origin)
        text += fmt::format("origin\t{}\t{}\t{}\t{}\n", field(item.source), field(item.key), field(item.value),
                            item.summary ? "summary" : "detail");
    return text;
}

std::optional<std::vector<CinemaOriginItem>> readMarker(const std::string& folder) {
    const std::string path = (std::filesystem::path(folder) / kMarkerFileName).string();
    std::error_code ec;
    if (!std::filesystem::exists(std::filesystem::symlink_status(path, ec))) return std::nullopt;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(fmt::format("{}: not a regular file; expected Darkroom's database marker", path));
    std::ifstream in(path, std::ios::binary);
    if (!in) throw Error(fmt::format("cannot read {}", path));
    std::vector<CinemaOriginItem> items;
    bool versioned = false;
    std::string line;
    int number = 0;
    while (std::getline(in, line)) {
        ++number;
        if (number > 10000) throw Error(fmt::format("{}: too many lines for Darkroom's database marker", path));
        if (line.empty() || line[0] == '#') continue;
        if (line == kVersionLine) {
            versioned = true;
            continue;
        }
        const auto f = splitTabs(line);
        if (f.size() == 5 && f[0] == "origin" && (f[4] == "summary" || f[4] == "detail")) {
            items.push_back({f[1], f[2], f[3], f[4] == "summary"});
            continue;
        }
        throw Error(fmt::format("{}:{}: '{}' is not a line of Darkroom's database marker (version 1)", path, number,
                                line.substr(0, 80)));
    }
    if (!versioned)
        throw Error(fmt::format("{}: no '{}' line; this is not a database marker this Darkroom writes", path,
                                "darkroom-database 1"));
    return items;
}

std::string describeOriginChange(const std::vector<CinemaOriginItem>& recorded,
                                 const std::vector<CinemaOriginItem>& now) {
    // Keyed by (source, key), in the order the items are given now (then
    // those recorded only).
    struct Pair {
        const CinemaOriginItem* before = nullptr;
        const CinemaOriginItem* after = nullptr;
    };
    std::vector<std::pair<std::string, std::string>> order;
    std::map<std::pair<std::string, std::string>, Pair> pairs;
    for (const auto& item : now) {
        auto [it, fresh] = pairs.try_emplace({item.source, item.key});
        if (fresh) order.emplace_back(item.source, item.key);
        it->second.after = &item;
    }
    for (const auto& item : recorded) {
        auto [it, fresh] = pairs.try_emplace({item.source, item.key});
        if (fresh) order.emplace_back(item.source, item.key);
        it->second.before = &item;
    }
    std::vector<std::string> sources;
    std::map<std::string, std::vector<std::string>> details, summaries;
    for (const auto& k : order) {
        const Pair& p = pairs.at(k);
        const std::string before = p.before ? p.before->value : "(none)";
        const std::string after = p.after ? p.after->value : "(none)";
        if (p.before && p.after && before == after) continue;
        const bool summary = (p.after ? p.after : p.before)->summary;
        if (details[k.first].empty() && summaries[k.first].empty()) sources.push_back(k.first);
        (summary ? summaries : details)[k.first].push_back(fmt::format("{} {} \u2192 {}", k.second, before, after));
    }
    std::string out;
    for (const auto& source : sources) {
        // A content hash says only that something changed: named when
        // nothing more telling did.
        const auto& what = details[source].empty() ? summaries[source] : details[source];
        std::string list;
        for (const auto& w : what) list += (list.empty() ? "" : ", ") + w;
        out += fmt::format("{}{} changed since the capture began ({})", out.empty() ? "" : "; ", source, list);
    }
    return out;
}

}  // namespace darkroom::cinema_detail
