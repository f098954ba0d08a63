// A database row as a typed row, and placeholder filling (row.h).
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/row.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

namespace darkroom {

namespace {

// One placeholder's text: the cell as written, or formatted with `spec`.
std::string formatCell(const std::string& cell, const std::string& spec, std::string_view what,
                       std::string_view placeholder) {
    if (spec.empty()) return cell;
    const std::string format = "{:" + spec + "}";
    double v = 0;
    const bool number = parseCsvNumber(cell, v);
    const char type = spec.back();
    // fmt does not reject every unknown presentation type; the ones it knows:
    const bool letter = (type >= 'a' && type <= 'z') || (type >= 'A' && type <= 'Z');
    if (letter && std::string_view(number ? "eEfFgGaAdxXobBc" : "s").find(type) == std::string_view::npos)
        throw Error(fmt::format("{}: placeholder {{{}}}: cannot format '{}' with '{}' (unknown type '{}'); expected a "
                                "format specification such as .2f, 6.1e or >8",
                                what, placeholder, cell, spec, type));
    try {
        if (number && std::string_view("dxXobBc").find(type) != std::string_view::npos) {
            if (!(std::isfinite(v) && v == std::round(v) && std::fabs(v) < 9.2e18))
                throw Error(fmt::format("{}: placeholder {{{}}}: '{}' is not an integer, which '{}' formats",
                                        what, placeholder, cell, spec));
            return fmt::format(fmt::runtime(format), static_cast<long long>(v));
        }
        if (number) return fmt::format(fmt::runtime(format), v);
        return fmt::format(fmt::runtime(format), cell);
    } catch (const fmt::format_error& e) {
        throw Error(fmt::format("{}: placeholder {{{}}}: cannot format '{}' with '{}' ({}); expected a "
                                "format specification such as .2f, 6.1e or >8",
                                what, placeholder, cell, spec, e.what()));
    }
}

}  // namespace

Row cinemaRow(const CinemaDatabase& db, std::size_t row) {
    std::vector<RowCell> cells;
    for (std::size_t c : db.parameterColumns()) cells.push_back({db.columns()[c].name, db.cell(row, c)});
    for (std::size_t c : db.fileColumns()) {
        const std::string& name = db.columns()[c].name;
        std::string path;
        if (!db.cell(row, c).empty()) {
            std::error_code ec;
            const std::filesystem::path p = std::filesystem::absolute(db.productPath(row, name), ec);
            path = (ec ? std::filesystem::path(db.productPath(row, name)) : p).lexically_normal().string();
        }
        cells.push_back({name, path});
    }
    return Row(std::move(cells));
}

bool hasRowPlaceholders(std::string_view pattern) {
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        if (pattern[i] != '{') continue;
        if (i + 1 < pattern.size() && pattern[i + 1] == '{') {
            ++i;
            continue;
        }
        return true;
    }
    return false;
}

std::string fillRowPlaceholders(std::string_view pattern, const Row& row, std::string_view what) {
    std::string out;
    for (std::size_t i = 0; i < pattern.size(); ++i) {
        const char c = pattern[i];
        if (c == '}') {
            if (i + 1 < pattern.size() && pattern[i + 1] == '}') {
                out += '}';
                ++i;
                continue;
            }
            throw Error(fmt::format("{}: a single '}}' at character {} of '{}'; write '}}}}' for a brace", what,
                                    i + 1, pattern));
        }
        if (c != '{') {
            out += c;
            continue;
        }
        if (i + 1 < pattern.size() && pattern[i + 1] == '{') {
            out += '{';
            ++i;
            continue;
        }
        const std::size_t close = pattern.find('}', i + 1);
        if (close == std::string_view::npos)
            throw Error(fmt::format("{}: '{{' at character {} of '{}' is not closed; write '{{{{' for a brace", what,
                                    i + 1, pattern));
        const std::string_view inside = pattern.substr(i + 1, close - i - 1);
        const std::size_t colon = inside.find(':');
        std::string name(inside.substr(0, colon));
        while (!name.empty() && name.back() == ' ') name.pop_back();
        while (!name.empty() && name.front() == ' ') name.erase(name.begin());
        const std::string spec = colon == std::string_view::npos ? "" : std::string(inside.substr(colon + 1));
        const std::string* cell = row.find(name);
        if (!cell)
            throw Error(fmt::format("{}: placeholder {{{}}} names no column of the row (columns: {})", what, inside,
                                    row.columnNames()));
        out += formatCell(*cell, spec, what, inside);
        i = close;
    }
    return out;
}

}  // namespace darkroom
