// A table row's cells and its text form (row.h).
#include <darkroom/error.h>
#include <darkroom/row.h>
#include <darkroom/strings.h>

namespace darkroom {

namespace {

std::string quoteRowValue(const std::string& v) {
    const bool plain = v.find_first_of(",=\"") == std::string::npos &&
                       (v.empty() || (v.front() != ' ' && v.back() != ' ' && v.front() != '\t' && v.back() != '\t'));
    if (plain) return v;
    std::string out = "\"";
    for (char c : v) {
        if (c == '"') out += '"';
        out += c;
    }
    return out + "\"";
}

// A value as written: a quoted one unquoted, "" read as one quote.
std::string unquote(std::string_view v) {
    if (v.size() < 2 || v.front() != '"' || v.back() != '"') return std::string(v);
    v = v.substr(1, v.size() - 2);
    std::string out;
    for (std::size_t j = 0; j < v.size(); ++j) {
        out += v[j];
        if (v[j] == '"' && j + 1 < v.size() && v[j + 1] == '"') ++j;
    }
    return out;
}

}  // namespace

Row::Row(std::vector<RowCell> cells) : cells_(std::move(cells)) {
    for (std::size_t i = 0; i < cells_.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (cells_[k].column == cells_[i].column)
                throw Error("a row gives column '" + cells_[i].column + "' twice");
}

const std::string* Row::find(std::string_view column) const {
    for (const RowCell& c : cells_)
        if (c.column == column) return &c.text;
    return nullptr;
}

std::string Row::columnNames() const {
    std::string s;
    for (const RowCell& c : cells_) s += (s.empty() ? "" : ", ") + c.column;
    return s.empty() ? std::string("none") : s;
}

std::vector<RowCell> parseNameValues(std::string_view text, std::string_view what) {
    std::vector<RowCell> out;
    std::size_t i = 0;
    while (i < text.size()) {
        // One "name=value" item up to the next comma outside quotes.
        std::string item;
        bool quoted = false;
        for (; i < text.size(); ++i) {
            const char c = text[i];
            if (c == '"') quoted = !quoted;
            if (c == ',' && !quoted) break;
            item += c;
        }
        ++i;
        if (quoted)
            throw Error(std::string(what) + " '" + std::string(text) +
                        "': unterminated quote; expected name=\"value\"");
        const std::string_view t = trimBlanks(item);
        if (t.empty()) continue;
        const std::size_t eq = t.find('=');
        if (eq == std::string_view::npos || trimBlanks(t.substr(0, eq)).empty())
            throw Error(std::string(what) + " '" + std::string(text) + "': '" + std::string(t) +
                        "' is not of the form name=value (e.g. 'phi=30, theta=45')");
        out.push_back({std::string(trimBlanks(t.substr(0, eq))), unquote(trimBlanks(t.substr(eq + 1)))});
    }
    return out;
}

std::string formatRow(const Row& row) {
    std::string out;
    for (const auto& [k, v] : row.cells()) out += (out.empty() ? "" : ", ") + k + "=" + quoteRowValue(v);
    return out;
}

Row parseRow(std::string_view text) {
    std::vector<RowCell> cells = parseNameValues(text, "row");
    for (std::size_t i = 0; i < cells.size(); ++i)
        for (std::size_t k = 0; k < i; ++k)
            if (cells[k].column == cells[i].column)
                throw Error("row '" + std::string(text) + "': column '" + cells[i].column + "' is given twice");
    return Row(std::move(cells));
}

}  // namespace darkroom
