#include "database_range.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/composable.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/product.h>

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

constexpr int kMaxLevels = 8;  // products nest a few folders deep (image/<phi>/0.png)

std::string findDatabase(const std::string& source) {
    if (source.empty())
        throw Error("range 'database': the image names no source product (metadata 'source'), so the database it "
                    "came from is unknown; connect a CinemaReader, or use range automatic or manual");
    std::error_code ec;
    // A product's folder and those above it; a composable image set's
    // buffer names the database folder itself.
    fs::path dir = fs::absolute(fs::path(source), ec);
    if (!fs::is_directory(dir, ec)) dir = dir.parent_path();
    for (int i = 0; i < kMaxLevels && !dir.empty(); ++i, dir = dir.parent_path()) {
        if (fs::is_regular_file(dir / "data.csv", ec)) return dir.string();
        if (dir == dir.parent_path()) break;
    }
    throw Error("range 'database': no folder above " + source + " holds a data.csv; the image was not read from a "
                "Cinema database");
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

// The rows whose products hold `channel`: one per entry (a composable image
// set's layer: its first row, which the reader assembles whole).
std::vector<std::size_t> entryRows(const CinemaDatabase& db) {
    std::vector<std::size_t> rows;
    if (!isComposableImageSet(db)) {
        for (std::size_t r = 0; r < db.rowCount(); ++r) rows.push_back(r);
        return rows;
    }
    for (const auto& image : composableImages(db))
        for (const auto& layer : image.layers)
            if (!layer.channels.empty()) rows.push_back(layer.channels.front().row);
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

void extend(DatabaseRange& r, const Buffer& b, const std::string& channel, bool positiveOnly) {
    if (!b.hasChannel(channel)) return;
    const float* f = b.hostFloat(channel);
    const std::uint32_t* u = f ? nullptr : b.hostUInt(channel);
    const float* z = b.hostFloat("Z");
    for (std::size_t i = 0; i < b.pixelCount(); ++i) {
        if (z && std::isinf(z[i]) && z[i] > 0) continue;
        const double v = f ? double(f[i]) : double(u[i]);
        if (!std::isfinite(v) || (positiveOnly && !(v > 0))) continue;
        r.low = r.found ? std::min(r.low, v) : v;
        r.high = r.found ? std::max(r.high, v) : v;
        r.found = true;
    }
}

bool fromComposableColumns(const CinemaDatabase& db, const std::string& channel, DatabaseRange& r) {
    const auto var = db.findColumn("CISChannelVar"), lo = db.findColumn("CISChannelVarMin"),
               hi = db.findColumn("CISChannelVarMax");
    if (!var || !lo || !hi) return false;
    for (std::size_t row = 0; row < db.rowCount(); ++row) {
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

// The range from the CIS columns, the cache file, or a scan (then cached).
DatabaseRange scanOrLookUp(const std::string& folder, const std::string& channel, bool positiveOnly,
                           const std::function<void(double)>& progress);

}  // namespace

DatabaseRange databaseRange(const std::string& source, const std::string& channel, bool positiveOnly,
                            const std::function<void(double)>& progress) {
    const std::string folder = findDatabase(source);
    const std::string key = folder + '\n' + channel + (positiveOnly ? "\nlog" : "\nlinear");
    const std::uint64_t csvStamp = mixStamp(kFnvBasis, (fs::path(folder) / "data.csv").string());
    {
        std::lock_guard<std::mutex> lock(g_mutex);
        const auto it = g_remembered.find(key);
        if (it != g_remembered.end() && it->second.csvStamp == csvStamp) return it->second.range;
    }
    DatabaseRange r = scanOrLookUp(folder, channel, positiveOnly, progress);
    std::lock_guard<std::mutex> lock(g_mutex);
    g_remembered[key] = {csvStamp, r};
    return r;
}

namespace {

DatabaseRange scanOrLookUp(const std::string& folder, const std::string& channel, bool positiveOnly,
                           const std::function<void(double)>& progress) {
    DatabaseRange r;
    r.database = folder;
    const CinemaDatabase db = CinemaDatabase::open(r.database);
    if (!positiveOnly && fromComposableColumns(db, channel, r)) {
        return r;
    }
    const std::vector<std::size_t> rows = entryRows(db);
    const std::uint64_t stamp = stampOf(db, rows);
    const fs::path cache = cacheFile(db);
    if (!cache.empty() && cached(cache, stamp, channel, positiveOnly, r)) {
        return r;
    }
    const bool composable = isComposableImageSet(db);
    for (std::size_t k = 0; k < rows.size(); ++k) {
        const auto image = composable ? readComposableRows(db, {rows[k]}) : readCinemaProduct(db.productPath(rows[k]));
        extend(r, *image, channel, positiveOnly);
        if (progress) progress(double(k + 1) / double(rows.size()));
    }
    remember(cache, stamp, channel, positiveOnly, r);
    return r;
}

}  // namespace

}  // namespace darkroom
