// SQL selection over data.csv, as TTK's CinemaQuery does it: the table is
// loaded into an in-memory SQLite database named `input` (numeric columns as
// REAL, NaN and empty cells as NULL; other columns as TEXT) and the user's
// WHERE expression picks rows. SQLite does the parsing, so the full
// expression language (AND/OR/NOT, comparisons, BETWEEN, IN, LIKE, functions)
// is available without a parser of our own.
#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/limits.h>

#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>

namespace darkroom {

namespace {

struct DbCloser {
    void operator()(sqlite3* d) const { sqlite3_close(d); }
};
struct StmtCloser {
    void operator()(sqlite3_stmt* s) const { sqlite3_finalize(s); }
};
using Db = std::unique_ptr<sqlite3, DbCloser>;
using Stmt = std::unique_ptr<sqlite3_stmt, StmtCloser>;

std::string quoteIdentifier(const std::string& name) {
    std::string out = "\"";
    for (char c : name) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

std::string_view trimmed(std::string_view s) {
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
    while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
    return s;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

}  // namespace

namespace {

// What SQLite's progress handler consults: the caller's stop flag and the
// node time limit, which a query with no end (WITH RECURSIVE ...) would
// otherwise never reach, as SQLite does not return between steps.
struct QueryWatch {
    const std::function<bool()>* stop;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::uint64_t limitMs = limit(Limit::NodeMilliseconds);
    bool cancelled = false, overTime = false;

    static int check(void* self) {
        auto& w = *static_cast<QueryWatch*>(self);
        if (*w.stop && (*w.stop)()) w.cancelled = true;
        const auto ms = std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::steady_clock::now() - w.start);
        if (w.limitMs && std::uint64_t(ms.count()) > w.limitMs) w.overTime = true;
        return w.cancelled || w.overTime;
    }
};

// Every step of the query under the watch; a stop becomes Cancelled or the
// time limit's InputError rather than SQLite's bare "interrupted".
template <class Fail>
std::vector<std::size_t> collectRows(sqlite3* db, sqlite3_stmt* sel, const QueryWatch& watch, const Fail& fail) {
    std::vector<std::size_t> rows;
    for (;;) {
        const int rc = sqlite3_step(sel);
        if (rc == SQLITE_DONE) break;
        if (rc == SQLITE_INTERRUPT && watch.cancelled) throw Cancelled();
        if (rc == SQLITE_INTERRUPT && watch.overTime)
            throw InputError(fail(fmt::format("ran past {} {:g}", limitOption(Limit::NodeMilliseconds),
                                              double(watch.limitMs) / 1000.0)).what());
        if (rc != SQLITE_ROW) throw fail(sqlite3_errmsg(db));
        rows.push_back(std::size_t(sqlite3_column_int64(sel, 0) - 1));
    }
    return rows;
}

}  // namespace

std::vector<std::size_t> CinemaDatabase::query(const std::string& sqlWhere, const std::function<bool()>& stop) const {
    std::string expr(trimmed(sqlWhere));
    if (lower(expr.substr(0, 6)) == "where ") expr = expr.substr(6);
    if (trimmed(expr).empty()) {
        std::vector<std::size_t> all(rowCount());
        for (std::size_t r = 0; r < all.size(); ++r) all[r] = r;
        return all;
    }
    const auto fail = [&](const std::string& why) -> Error {
        return Error(fmt::format("query '{}' on Cinema database '{}': {}", sqlWhere, folder_, why));
    };

    sqlite3* raw = nullptr;
    if (sqlite3_open_v2(":memory:", &raw, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) != SQLITE_OK) {
        Db guard(raw);
        throw fail("cannot create an in-memory SQLite database");
    }
    Db db(raw);
    // The row number travels in SQLite's rowid; a column named like one of its
    // aliases hides that alias, so use one that no column shadows.
    std::string rowidName;
    for (const char* alias : {"rowid", "_rowid_", "oid"}) {
        bool shadowed = false;
        for (const auto& c : columns_) shadowed |= lower(c.name) == alias;
        if (!shadowed) {
            rowidName = alias;
            break;
        }
    }
    if (rowidName.empty()) throw fail("columns named rowid, _rowid_ and oid leave no way to number the rows");

    std::string create = "CREATE TABLE input (", insert = "INSERT INTO input (" + rowidName;
    std::string values = ") VALUES (?";
    for (std::size_t c = 0; c < columns_.size(); ++c) {
        const std::string name = columns_[c].name.empty() ? fmt::format("column{}", c + 1) : columns_[c].name;
        create += (c ? ", " : "") + quoteIdentifier(name) + (columns_[c].numeric ? " REAL" : " TEXT");
        insert += ", " + quoteIdentifier(name);
        values += ", ?";
    }
    create += ")";
    insert += values + ")";
    char* message = nullptr;
    if (sqlite3_exec(db.get(), create.c_str(), nullptr, nullptr, &message) != SQLITE_OK) {
        const std::string why = message ? message : "unknown error";
        sqlite3_free(message);
        throw fail("cannot create the table (duplicate column names?): " + why);
    }
    sqlite3_exec(db.get(), "BEGIN", nullptr, nullptr, nullptr);
    sqlite3_stmt* rawInsert = nullptr;
    if (sqlite3_prepare_v2(db.get(), insert.c_str(), -1, &rawInsert, nullptr) != SQLITE_OK)
        throw fail(std::string("cannot prepare the table: ") + sqlite3_errmsg(db.get()));
    const Stmt ins(rawInsert);
    for (std::size_t r = 0; r < rowCount(); ++r) {
        sqlite3_reset(ins.get());
        sqlite3_bind_int64(ins.get(), 1, sqlite3_int64(r) + 1);
        for (std::size_t c = 0; c < columns_.size(); ++c) {
            const int at = int(c) + 2;
            if (columns_[c].numeric) {
                const double v = number(r, c);
                if (std::isnan(v)) sqlite3_bind_null(ins.get(), at);
                else sqlite3_bind_double(ins.get(), at, v);
            } else {
                const std::string& s = cell(r, c);
                sqlite3_bind_text(ins.get(), at, s.data(), int(s.size()), SQLITE_TRANSIENT);
            }
        }
        if (sqlite3_step(ins.get()) != SQLITE_DONE)
            throw fail(std::string("cannot load data.csv into SQLite: ") + sqlite3_errmsg(db.get()));
    }
    sqlite3_exec(db.get(), "COMMIT", nullptr, nullptr, nullptr);
    // No value the expression makes may be much longer than what data.csv
    // holds (randomblob(2e9) would otherwise allocate it).
    std::size_t longest = 0;
    for (std::size_t r = 0; r < rowCount(); ++r)
        for (std::size_t c = 0; c < columns_.size(); ++c) longest = std::max(longest, cell(r, c).size());
    sqlite3_limit(db.get(), SQLITE_LIMIT_LENGTH, int(std::min<std::size_t>(std::max<std::size_t>(longest + 1, 16u << 20), 1u << 30)));

    const std::string select =
        "SELECT " + rowidName + " FROM input WHERE (" + expr + "\n) ORDER BY " + rowidName;
    sqlite3_stmt* rawSelect = nullptr;
    const char* tail = nullptr;
    if (sqlite3_prepare_v2(db.get(), select.c_str(), -1, &rawSelect, &tail) != SQLITE_OK) {
        Stmt guard(rawSelect);
        throw fail(std::string(sqlite3_errmsg(db.get())) +
                   "; expected an SQL WHERE expression over the columns, e.g. \"phi > 0 AND theta = 0\" "
                   "(text in 'single quotes', names with spaces in \"double quotes\")");
    }
    const Stmt sel(rawSelect);
    if (tail && !trimmed(tail).empty()) throw fail("expected one expression, found more after it");
    QueryWatch watch{&stop};
    sqlite3_progress_handler(db.get(), 4096, &QueryWatch::check, &watch);
    return collectRows(db.get(), sel.get(), watch, fail);
}

bool CinemaDatabase::looksLikeSql(std::string_view q) {
    // The simple form is "name=value, name=value" with values in "double
    // quotes" when needed; anything with comparison operators, parentheses,
    // single-quoted text or SQL keywords is SQL.
    bool inQuotes = false;
    std::string word;
    const auto keyword = [&]() {
        const std::string w = lower(word);
        word.clear();
        return w == "and" || w == "or" || w == "not" || w == "like" || w == "in" || w == "between" ||
               w == "is" || w == "glob" || w == "null";
    };
    for (char c : q) {
        if (c == '"') inQuotes = !inQuotes;
        if (inQuotes) continue;
        if (c == '<' || c == '>' || c == '!' || c == '(' || c == ')' || c == '\'') return true;
        if (std::isalnum(static_cast<unsigned char>(c)) || c == '_') {
            word += c;
        } else if (!word.empty() && keyword()) {
            return true;
        }
    }
    return !word.empty() && keyword();
}

std::vector<std::size_t> CinemaDatabase::selectWhere(const std::string& where, const std::function<bool()>& stop) const {
    return looksLikeSql(where) ? query(where, stop) : select(parseQuery(where));
}

}  // namespace darkroom
