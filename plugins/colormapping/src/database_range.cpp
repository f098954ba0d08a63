#include "database_range.h"

#include "value_histogram.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/product_database.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/product.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <mutex>
#include <set>
#include <sstream>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

std::string findDatabase(const std::string& source) {
    if (source.empty())
        throw Error("range 'database': the image names no source product (metadata 'source'), so the database it "
                    "came from is unknown; connect a CinemaReader, or use range automatic or manual");
    std::string folder = databaseOfProduct(source);
    if (folder.empty())
        throw Error("range 'database': no folder above " + source + " holds a data.csv; the image was not read from "
                    "a Cinema database");
    return folder;
}

constexpr std::uint64_t kFnvBasis = 0xcbf29ce484222325ULL;

// FNV-1a over bytes: stamps and cache file names, not security.
std::uint64_t fnv(std::uint64_t h, const void* bytes, std::size_t n) {
    for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<const std::uint8_t*>(bytes)[i]) * 0x100000001b3ULL;
    return h;
}

// A file's path, size and modification time, folded into `h`.
std::uint64_t mixStamp(std::uint64_t h, const std::string& path) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    const auto time = ec ? 0 : fs::last_write_time(path, ec).time_since_epoch().count();
    const std::uint64_t values[2] = {std::uint64_t(ec ? 0 : size), std::uint64_t(time)};
    return fnv(fnv(h, values, sizeof values), path.data(), path.size());
}

// The rows of `selection` (--where syntax; empty selects every row), as a set.
std::set<std::size_t> selectedRows(const CinemaDatabase& db, const std::string& selection) {
    const std::vector<std::size_t> rows = db.selectWhere(selection);
    return {rows.begin(), rows.end()};
}

// The selected rows whose products hold `channel`: one per entry (a
// composable image set's layer: its first row, which the reader assembles
// whole, counted when any of the layer's rows is selected).
std::vector<std::size_t> entryRows(const CinemaDatabase& db, const std::set<std::size_t>& selected) {
    std::vector<std::size_t> rows;
    if (!isComposableImageSet(db)) return {selected.begin(), selected.end()};
    for (const auto& image : composableImages(db))
        for (const auto& layer : image.layers) {
            bool any = false;
            for (const auto& c : layer.channels) any = any || selected.count(c.row);
            if (any && !layer.channels.empty()) rows.push_back(layer.channels.front().row);
        }
    return rows;
}

std::uint64_t stampOf(const CinemaDatabase& db, const std::vector<std::size_t>& rows) {
    std::uint64_t h = mixStamp(kFnvBasis, db.csvPath());
    std::set<std::string> seen;
    for (std::size_t r = 0; r < db.rowCount(); ++r) {
        std::string p;
        try {
            p = db.productPath(r);
        } catch (const Error&) {
            continue;  // an empty cell: no product
        }
        if (seen.insert(p).second) h = mixStamp(h, p);
    }
    return mixStamp(h, std::to_string(rows.size()));
}

fs::path cacheFile(const CinemaDatabase& db) {
    const char* xdg = std::getenv("XDG_CACHE_HOME");
    const char* home = std::getenv("HOME");
    const fs::path base = xdg && *xdg ? fs::path(xdg) : home && *home ? fs::path(home) / ".cache" : fs::path();
    if (base.empty()) return {};
    const std::string csv = fs::absolute(db.csvPath()).lexically_normal().string();
    std::ostringstream name;
    name << std::hex << fnv(kFnvBasis, csv.data(), csv.size()) << ".txt";
    return base / "darkroom" / "ranges" / name.str();
}

// Lines "stamp<TAB>channel<TAB>positiveOnly<TAB>low<TAB>high<TAB>found".
bool cached(const fs::path& file, std::uint64_t stamp, const std::string& channel, bool positiveOnly,
            DatabaseRange& out) {
    std::ifstream in(file);
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream f(line);
        std::uint64_t s = 0;
        std::string c;
        int pos = 0, found = 0;
        double lo = 0, hi = 0;
        if (!(f >> s) || f.get() != '\t' || !std::getline(f, c, '\t') || !(f >> pos >> lo >> hi >> found)) continue;
        if (s != stamp || c != channel || bool(pos) != positiveOnly) continue;
        out.low = lo, out.high = hi, out.found = found != 0;
        return true;
    }
    return false;
}

void remember(const fs::path& file, std::uint64_t stamp, const std::string& channel, bool positiveOnly,
              const DatabaseRange& r) {
    if (file.empty()) return;
    try {
        std::error_code ec;
        fs::create_directories(file.parent_path(), ec);
        std::string text;
        {
            std::ifstream in(file);
            for (std::string line; std::getline(in, line);)
                if (line.rfind(std::to_string(stamp) + "\t", 0) == 0) text += line + "\n";  // same state only
        }
        std::ostringstream add;
        add.precision(17);
        add << stamp << '\t' << channel << '\t' << int(positiveOnly) << ' ' << r.low << ' ' << r.high << ' '
            << int(r.found) << '\n';
        const std::string tmp = createTemporaryFile(file.string());
        std::ofstream(tmp) << text << add.str();
        commitFile(tmp, file.string());
    } catch (const std::exception&) {
        // No cache (a read-only home): the next run scans again.
    }
}

// Calls f(v) for every finite value of `channel` on geometry (positive ones
// only, for a log scale).
template <typename F>
void forEachValue(const Buffer& b, const std::string& channel, bool positiveOnly, F&& f) {
    if (!b.hasChannel(channel)) return;
    const float* v = b.hostFloat(channel);
    const std::uint32_t* u = v ? nullptr : b.hostUInt(channel);
    const float* z = b.hostFloat("Z");
    for (std::size_t i = 0; i < b.pixelCount(); ++i) {
        if (z && std::isinf(z[i]) && z[i] > 0) continue;
        const double x = v ? double(v[i]) : double(u[i]);
        if (!std::isfinite(x) || (positiveOnly && !(x > 0))) continue;
        f(x);
    }
}

void extend(DatabaseRange& r, const Buffer& b, const std::string& channel, bool positiveOnly) {
    forEachValue(b, channel, positiveOnly, [&r](double v) {
        r.low = r.found ? std::min(r.low, v) : v;
        r.high = r.found ? std::max(r.high, v) : v;
        r.found = true;
    });
}

bool fromComposableColumns(const CinemaDatabase& db, const std::set<std::size_t>& selected,
                           const std::string& channel, DatabaseRange& r) {
    const auto var = db.findColumn("CISChannelVar"), lo = db.findColumn("CISChannelVarMin"),
               hi = db.findColumn("CISChannelVarMax");
    if (!var || !lo || !hi) return false;
    for (const std::size_t row : selected) {
        if (db.cell(row, *var) != channel) continue;
        const double a = db.number(row, *lo), b = db.number(row, *hi);
        if (!std::isfinite(a) || !std::isfinite(b)) continue;
        r.low = r.found ? std::min(r.low, a) : a;
        r.high = r.found ? std::max(r.high, b) : b;
        r.found = true;
    }
    return r.found;
}

// Ranges found in this process, by database, channel and scale, with the
// stamp of the data.csv they were found for: a --foreach run asks once per
// entry, and each ask would otherwise parse data.csv and stat every product
// again (quadratic in the entries).
struct Remembered {
    std::uint64_t csvStamp = 0;
    DatabaseRange range;
};
std::mutex g_mutex;
std::map<std::string, Remembered> g_remembered;

using Progress = std::function<void(double)>;

// What is asked: the channel's range, on a log scale, clipped at percentiles.
struct Request {
    std::string channel;
    bool positiveOnly = false;
    double clip = 0;
    std::string selection;  // --where syntax; empty: every row
};

// The request as the cache file names it: the channel, the clip and the
// selection when set (one line of text: no tab or newline).
std::string cacheKey(const Request& q) {
    std::ostringstream key;
    key.precision(17);
    key << q.channel;
    if (q.clip > 0) key << " clip=" << q.clip;
    if (!q.selection.empty()) key << " where=" << q.selection;
    std::string text = key.str();
    std::replace_if(text.begin(), text.end(), [](char c) { return c == '\t' || c == '\n' || c == '\r'; }, ' ');
    return text;
}

// The range from the CIS columns, the cache file, or a scan (then cached).
DatabaseRange scanOrLookUp(const std::string& folder, const Request& q, const Progress& progress);

}  // namespace

DatabaseRange databaseRange(const std::string& source, const std::string& selection, const std::string& channel,
                            bool positiveOnly, double clip, const std::function<void(double)>& progress) {
    const std::string folder = findDatabase(source);
    const Request q{channel, positiveOnly, clip, selection};
    const std::string key = folder + '\n' + cacheKey(q) + (positiveOnly ? "\nlog" : "\nlinear");
    const std::uint64_t csvStamp = mixStamp(kFnvBasis, (fs::path(folder) / "data.csv").string());
    {
        std::lock_guard<std::mutex> lock(g_mutex);
        const auto it = g_remembered.find(key);
        if (it != g_remembered.end() && it->second.csvStamp == csvStamp) return it->second.range;
    }
    DatabaseRange r = scanOrLookUp(folder, q, progress);
    std::lock_guard<std::mutex> lock(g_mutex);
    g_remembered[key] = {csvStamp, r};
    return r;
}

namespace {

// Reads every entry of `rows` in turn, as CinemaReader reads it (a
// composable set's layers whole), reporting progress from `from` to `to`.
template <typename F>
void forEachEntry(const CinemaDatabase& db, const std::vector<std::size_t>& rows, const Progress& progress,
                  double from, double to, F&& f) {
    const bool composable = isComposableImageSet(db);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto image = composable ? readComposableRows(db, {rows[k]}) : readCinemaProduct(db.productPath(rows[k]));
        f(*image);
        if (progress) progress(from + (to - from) * double(k + 1) / double(rows.size()));
    }
}

// The clip-th and (100 - clip)-th percentiles of the values in [whole.low,
// whole.high] (their log10 for a log scale): a histogram, then a finer one
// inside each bin holding a wanted rank (value_histogram.h). The rank is
// that of ColorMapping's per-image percentiles: round(q (n - 1)).
DatabaseRange percentiles(const CinemaDatabase& db, const std::vector<std::size_t>& rows, const Request& q,
                          const DatabaseRange& whole, const Progress& progress) {
    using colormapping::ValueHistogram;
    const auto scaled = [&q](double v) { return q.positiveOnly ? std::log10(v) : v; };
    ValueHistogram coarse(scaled(whole.low), scaled(whole.high));
    forEachEntry(db, rows, progress, 0.0, 0.5, [&](const Buffer& b) {
        forEachValue(b, q.channel, q.positiveOnly, [&](double v) { coarse.add(scaled(v)); });
    });
    DatabaseRange r = whole;
    if (coarse.count() == 0) return r;
    const auto rankAt = [&](double fraction) {
        return std::uint64_t(std::llround(fraction * double(coarse.count() - 1)));
    };
    const std::uint64_t rankLow = rankAt(q.clip / 100.0), rankHigh = rankAt(1.0 - q.clip / 100.0);
    const ValueHistogram::Bin binLow = coarse.binOfRank(rankLow), binHigh = coarse.binOfRank(rankHigh);
    ValueHistogram fineLow(binLow.low, binLow.high), fineHigh(binHigh.low, binHigh.high);
    forEachEntry(db, rows, progress, 0.5, 1.0, [&](const Buffer& b) {
        forEachValue(b, q.channel, q.positiveOnly, [&](double v) {
            const double x = scaled(v);
            const std::size_t k = coarse.binOf(x);
            if (k == binLow.index) fineLow.add(x);
            if (k == binHigh.index) fineHigh.add(x);
        });
    });
    const auto unscaled = [&q](double v) { return q.positiveOnly ? std::pow(10.0, v) : v; };
    r.low = std::max(whole.low, unscaled(fineLow.binOfRank(rankLow, binLow.below).low));
    r.high = std::min(whole.high, unscaled(fineHigh.binOfRank(rankHigh, binHigh.below).high));
    return r;
}

DatabaseRange scanOrLookUp(const std::string& folder, const Request& q, const Progress& progress) {
    DatabaseRange r;
    r.database = folder;
    const CinemaDatabase db = CinemaDatabase::open(r.database);
    const std::set<std::size_t> selected = selectedRows(db, q.selection);
    if (q.clip <= 0 && !q.positiveOnly && fromComposableColumns(db, selected, q.channel, r)) return r;
    const std::vector<std::size_t> rows = entryRows(db, selected);
    const std::uint64_t stamp = stampOf(db, rows);
    const fs::path cache = cacheFile(db);
    if (!cache.empty() && cached(cache, stamp, cacheKey(q), q.positiveOnly, r)) return r;
    if (q.clip > 0) {
        // The minimum and maximum first (cached, or from the composable columns).
        const DatabaseRange whole = scanOrLookUp(folder, {q.channel, q.positiveOnly, 0.0, q.selection}, {});
        r = whole.found ? percentiles(db, rows, q, whole, progress) : whole;
    } else {
        forEachEntry(db, rows, progress, 0.0, 1.0,
                     [&](const Buffer& b) { extend(r, b, q.channel, q.positiveOnly); });
    }
    remember(cache, stamp, cacheKey(q), q.positiveOnly, r);
    return r;
}

}  // namespace

}  // namespace darkroom
