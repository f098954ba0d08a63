// Opening a Cinema database and looking entries up by parameter values.
#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/strings.h>
#include <darkroom/data/cinema/naming.h>
#include <darkroom/row.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <limits>
#include <string_view>
#include <unordered_set>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// At most `limit` items, then how many there are in all: error messages must
// stay readable for a column with 10,000 distinct time steps.
std::string listValues(const std::vector<std::string>& values, std::size_t limit = 24) {
    std::string out;
    for (std::size_t i = 0; i < values.size() && i < limit; ++i) {
        if (i) out += ", ";
        out += values[i].empty() ? std::string("(empty)") : values[i];
    }
    if (values.size() > limit) out += fmt::format(", ... ({} values in all)", values.size());
    return out.empty() ? std::string("(none)") : out;
}

bool sameNumber(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// A value written bare reads back as itself in both query forms: numbers and
// plain words, never one that SQL detection would take for a keyword.
bool isBareQueryValue(const std::string& v) {
    for (char c : v)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '.' && c != '-' && c != '+' && c != '_') return false;
    return !CinemaDatabase::looksLikeSql(v);
}

// Query values are quoted unless bare (isBareQueryValue): text from data is
// never read as query syntax (a value "'a' OR 1" selects only its own row).
std::string quoteQueryValue(const std::string& v) {
    if (isBareQueryValue(v)) return v;
    std::string out = "\"";
    for (char c : v) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

}  // namespace

CinemaDatabase CinemaDatabase::open(const std::string& path, const CsvReadOptions& options) {
    CinemaDatabase db;
    std::error_code ec;
    if (fs::is_directory(path, ec)) {
        db.folder_ = path;
        db.csvPath_ = (fs::path(path) / "data.csv").string();
        if (!fs::exists(db.csvPath_, ec))
            throw InputError(fmt::format("'{}' is not a Cinema database: it has no data.csv", path));
    } else if (fs::exists(path, ec)) {
        // A mesh or image given where a database was meant would otherwise be
        // read as a one-column table of its bytes.
        if (fs::path(path).extension() != ".csv")
            throw InputError(fmt::format("'{}' is not a Cinema database: expected a folder holding data.csv, or a "
                                         ".csv file",
                                         path));
        db.csvPath_ = path;
        db.folder_ = fs::path(path).parent_path().string();
        if (db.folder_.empty()) db.folder_ = ".";
    } else {
        throw InputError(fmt::format("cannot open Cinema database '{}': no such file or directory", path));
    }
    db.table_ = readCsvFile(db.csvPath_, options);

    const std::size_t ncols = db.table_.header.size();
    db.columns_.resize(ncols);
    db.numbers_.resize(ncols);
    for (std::size_t c = 0; c < ncols; ++c) {
        CinemaColumn& col = db.columns_[c];
        col.name = db.table_.header[c];
        col.isFile = isCinemaFileColumn(col.name);
        // Numeric when every non-empty cell is a number (and there is one).
        std::vector<double> values(db.table_.rows.size(), kNaN);
        bool numeric = true, any = false;
        for (std::size_t r = 0; r < db.table_.rows.size() && numeric; ++r) {
            const std::string& s = db.table_.rows[r][c];
            if (s.empty()) continue;
            any = true;
            numeric = parseCsvNumber(s, values[r]);
        }
        col.numeric = numeric && any && !col.isFile;
        if (col.numeric) {
            // Distinct by value, spelled as first written ("1.0" and "1" are one value).
            std::vector<std::pair<double, std::string>> distinct;
            double lo = std::numeric_limits<double>::infinity(), hi = -lo;
            for (std::size_t r = 0; r < values.size(); ++r) {
                if (std::isnan(values[r])) {
                    ++col.missing;
                    continue;
                }
                lo = std::min(lo, values[r]);
                hi = std::max(hi, values[r]);
                distinct.emplace_back(values[r], db.table_.rows[r][c]);
            }
            std::stable_sort(distinct.begin(), distinct.end(),
                             [](const auto& a, const auto& b) { return a.first < b.first; });
            distinct.erase(std::unique(distinct.begin(), distinct.end(),
                                       [](const auto& a, const auto& b) { return a.first == b.first; }),
                           distinct.end());
            for (auto& d : distinct) col.distinct.push_back(std::move(d.second));
            col.minimum = distinct.empty() ? kNaN : lo;
            col.maximum = distinct.empty() ? kNaN : hi;
            db.numbers_[c] = std::move(values);
        } else {
            col.minimum = col.maximum = kNaN;
            // Hashed: a column of n distinct strings is linear, not n^2 comparisons.
            std::unordered_set<std::string_view> seen;
            for (const auto& row : db.table_.rows) {
                const std::string& s = row[c];
                if (s.empty()) ++col.missing;
                if (seen.insert(s).second) col.distinct.push_back(s);
            }
        }
    }
    return db;
}

std::optional<std::size_t> CinemaDatabase::findColumn(std::string_view name) const {
    for (std::size_t c = 0; c < columns_.size(); ++c)
        if (columns_[c].name == name) return c;
    return std::nullopt;
}

std::size_t CinemaDatabase::column(std::string_view name) const {
    if (auto c = findColumn(name)) return *c;
    std::vector<std::string> names;
    for (const auto& c : columns_) names.push_back(c.name);
    throw Error(fmt::format("Cinema database '{}' has no column '{}'; its columns are: {}", folder_,
                            name, listValues(names, 1000)));
}

std::vector<std::size_t> CinemaDatabase::fileColumns() const {
    std::vector<std::size_t> out;
    for (std::size_t c = 0; c < columns_.size(); ++c)
        if (columns_[c].isFile) out.push_back(c);
    return out;
}

std::vector<std::size_t> CinemaDatabase::parameterColumns() const {
    std::vector<std::size_t> out;
    for (std::size_t c = 0; c < columns_.size(); ++c)
        if (!columns_[c].isFile) out.push_back(c);
    return out;
}

const std::string& CinemaDatabase::cell(std::size_t row, std::size_t column) const {
    return table_.rows.at(row).at(column);
}

double CinemaDatabase::number(std::size_t row, std::size_t column) const {
    const auto& v = numbers_.at(column);
    return v.empty() ? kNaN : v.at(row);
}

std::string CinemaDatabase::productPath(std::size_t row, std::string_view fileColumn) const {
    std::size_t c;
    if (fileColumn.empty()) {
        const auto files = fileColumns();
        if (files.empty())
            throw Error(fmt::format("Cinema database '{}' has no FILE column, so its entries have no "
                                    "products; name a column that holds file names",
                                    folder_));
        c = files.front();
    } else {
        c = column(fileColumn);
    }
    const std::string& name = cell(row, c);
    if (name.empty())
        throw Error(fmt::format("{}:{}: the {} cell is empty; expected a product file name", csvPath_,
                                line(row), columns_[c].name));
    const fs::path p(name);
    return (p.is_absolute() ? p : (fs::path(folder_) / p)).lexically_normal().string();
}

std::vector<CinemaConstraint> CinemaDatabase::parseQuery(std::string_view query) {
    std::vector<CinemaConstraint> out;
    for (auto& [column, value] : parseNameValues(query, "query")) out.push_back({std::move(column), std::move(value)});
    return out;
}

namespace {

// A constraint resolved against a column: the exact number or text to match.
struct Matcher {
    std::size_t column;
    bool numeric;
    double number;
    std::string text;
    bool impossible = false;  // the value occurs nowhere in the column
};

}  // namespace

// Resolution shared by find() and select(); `notes` collects snapped values.
static std::vector<Matcher> resolve(const CinemaDatabase& db,
                                    const std::vector<CinemaConstraint>& constraints,
                                    std::vector<std::string>& notes) {
    std::vector<Matcher> out;
    for (const auto& k : constraints) {
        Matcher m{db.column(k.column), false, kNaN, k.value};
        const CinemaColumn& col = db.columns()[m.column];
        m.numeric = col.numeric;
        if (!col.numeric) {
            m.impossible = std::find(col.distinct.begin(), col.distinct.end(), k.value) ==
                           col.distinct.end();
            out.push_back(std::move(m));
            continue;
        }
        if (k.value.empty()) {  // empty = missing = NaN
            m.impossible = col.missing == 0;
            out.push_back(std::move(m));
            continue;
        }
        double v;
        if (!parseCsvNumber(k.value, v))
            throw Error(fmt::format("Cinema database '{}': '{}={}': column {} is numeric; expected a "
                                    "number (values: {})",
                                    db.path(), k.column, k.value, col.name, listValues(col.distinct)));
        if (std::isnan(v)) {
            m.impossible = col.missing == 0;
            out.push_back(std::move(m));
            continue;
        }
        // Snap to the nearest value present, but only within the column's
        // widest spacing: phi=31 finds 30, phi=1000 finds nothing.
        std::vector<double> d;
        for (const auto& s : col.distinct) {
            double x;
            parseCsvNumber(s, x);
            d.push_back(x);
        }
        std::size_t best = 0;
        double maxGap = 0;
        for (std::size_t i = 0; i < d.size(); ++i) {
            if (std::fabs(d[i] - v) < std::fabs(d[best] - v)) best = i;
            if (i) maxGap = std::max(maxGap, d[i] - d[i - 1]);
        }
        const double tol = 1e-9 * std::max(1.0, std::fabs(v));
        if (d.empty() || !(std::fabs(d[best] - v) <= std::max(tol, maxGap * 0.5))) {
            m.impossible = true;
        } else {
            if (std::fabs(d[best] - v) > tol)
                notes.push_back(fmt::format("{}={} is not in the database; using the nearest value {}",
                                            col.name, k.value, col.distinct[best]));
            m.number = d[best];
        }
        out.push_back(std::move(m));
    }
    return out;
}

static bool matches(const CinemaDatabase& db, std::size_t row, const std::vector<Matcher>& ms) {
    for (const auto& m : ms) {
        if (m.impossible) return false;
        if (m.numeric ? !sameNumber(db.number(row, m.column), m.number)
                      : db.cell(row, m.column) != m.text)
            return false;
    }
    return true;
}

std::vector<std::size_t> CinemaDatabase::select(const std::vector<CinemaConstraint>& constraints) const {
    std::vector<std::string> notes;
    const auto ms = resolve(*this, constraints, notes);
    std::vector<std::size_t> out;
    for (std::size_t r = 0; r < rowCount(); ++r)
        if (matches(*this, r, ms)) out.push_back(r);
    return out;
}

CinemaMatch CinemaDatabase::find(const std::vector<CinemaConstraint>& constraints) const {
    if (rowCount() == 0)
        throw Error(fmt::format("Cinema database '{}' has no entries ({} holds only a header)", folder_,
                                csvPath_));
    CinemaMatch match;
    const auto ms = resolve(*this, constraints, match.notes);
    for (std::size_t r = 0; r < rowCount(); ++r)
        if (matches(*this, r, ms)) {
            match.row = r;
            return match;
        }
    std::string query, available;
    for (const auto& k : constraints) {
        query += (query.empty() ? "" : ", ") + k.column + "=" + k.value;
        const CinemaColumn& col = columns_[column(k.column)];
        available += fmt::format("\n  {}: {}", col.name, listValues(col.distinct));
    }
    throw Error(fmt::format("no entry of Cinema database '{}' matches '{}'; available values:{}", folder_,
                            query, available));
}

std::string CinemaDatabase::formatParameters(std::size_t row) const {
    std::string out;
    for (std::size_t c : parameterColumns()) {
        if (!out.empty()) out += ", ";
        out += columns_[c].name + "=" + quoteQueryValue(cell(row, c));
    }
    return out;
}

std::string CinemaDatabase::entryName(std::size_t row) const {
    std::vector<std::pair<std::string, std::string>> p;
    for (std::size_t c : parameterColumns()) p.emplace_back(columns_[c].name, cell(row, c));
    return cinemaEntryName(p);
}

}  // namespace darkroom
