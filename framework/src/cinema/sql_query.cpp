// SQL selection over data.csv, as TTK's CinemaQuery does it: the table is
// loaded into an in-memory SQLite database named `input` (numeric columns as
// REAL, NaN and empty cells as NULL; other columns as TEXT) and the user's
// WHERE expression picks rows. SQLite does the parsing, so the full
// expression language (AND/OR/NOT, comparisons, BETWEEN, IN, LIKE, functions)
// is available without a parser of our own.
#include <darkroom/error.h>
#include <darkroom/framework/cinema/database.h>

#include <fmt/format.h>
#include <sqlite3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
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

std::vector<std::size_t> CinemaDatabase::query(const std::string& sqlWhere) const {
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
    std::vector<std::size_t> rows;
    for (;;) {
        const int rc = sqlite3_step(sel.get());
        if (rc == SQLITE_DONE) break;
        if (rc != SQLITE_ROW) throw fail(sqlite3_errmsg(db.get()));
        rows.push_back(std::size_t(sqlite3_column_int64(sel.get(), 0) - 1));
    }
    return rows;
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

std::vector<std::size_t> CinemaDatabase::selectWhere(const std::string& where) const {
    return looksLikeSql(where) ? query(where) : select(parseQuery(where));
}

}  // namespace darkroom
