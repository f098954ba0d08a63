// The tolerant data.csv reader. Irregularities are collected per kind so a
// file with a thousand short rows yields one warning, not a thousand.
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/strings.h>
#include <darkroom/input_file.h>

#include <fmt/format.h>

#include <array>
#include <map>
#include <set>

namespace darkroom {

namespace {

enum class Irregularity {
    ShortRow,
    LongRow,
    UnterminatedQuote,
    TextAfterQuote,
    EmptyColumnName,
    DuplicateColumnName,
};

const char* describe(Irregularity k) {
    switch (k) {
        case Irregularity::ShortRow: return "row has fewer cells than the header; padded with empty cells";
        case Irregularity::LongRow: return "row has more cells than the header; extra cells ignored";
        case Irregularity::UnterminatedQuote: return "quoted cell is not closed before the end of the line";
        case Irregularity::TextAfterQuote: return "text after the closing quote of a cell; kept as part of the cell";
        case Irregularity::EmptyColumnName: return "empty column name in the header";
        case Irregularity::DuplicateColumnName: return "duplicate column name in the header; lookups by name use the first";
    }
    return "irregular row";
}

// Records the first line and the count of every kind; throws at once when strict.
class IrregularityLog {
public:
    IrregularityLog(const std::string& source, bool strict) : source_(source), strict_(strict) {}

    void add(Irregularity kind, int line, const std::string& detail) {
        if (strict_)
            throw Error(fmt::format("{}:{}: {} ({}); expected a regular CSV row (strict mode)",
                                    source_, line, describe(kind), detail));
        auto [it, inserted] = seen_.try_emplace(kind, Entry{line, 0, detail});
        ++it->second.count;
    }

    Diagnostics diagnostics() const {
        Diagnostics out;
        for (const auto& [kind, e] : seen_) {
            std::string msg = fmt::format("{} ({})", describe(kind), e.detail);
            if (e.count > 1) msg += fmt::format("; {} occurrences in all", e.count);
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            d.where = fmt::format("{}:{}", source_, e.line);
            d.message = std::move(msg);
            out.push_back(std::move(d));
        }
        return out;
    }

private:
    struct Entry {
        int line;
        int count;
        std::string detail;
    };
    const std::string& source_;
    bool strict_;
    std::map<Irregularity, Entry> seen_;
};

// Splits one physical line into cells. Quoted cells may contain commas and
// doubled quotes; they may not span lines (no Cinema writer produces that,
// and a stray quote would otherwise swallow the rest of the file).
std::vector<std::string> splitLine(std::string_view line, int lineNo, IrregularityLog& log) {
    std::vector<std::string> cells;
    std::size_t i = 0;
    for (;;) {
        while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
        std::string cell;
        if (i < line.size() && line[i] == '"') {
            ++i;
            bool closed = false;
            while (i < line.size()) {
                if (line[i] == '"') {
                    if (i + 1 < line.size() && line[i + 1] == '"') {
                        cell += '"';
                        i += 2;
                        continue;
                    }
                    closed = true;
                    ++i;
                    break;
                }
                cell += line[i++];
            }
            if (!closed)
                log.add(Irregularity::UnterminatedQuote, lineNo,
                        fmt::format("cell {}", cells.size() + 1));
            const std::size_t end = line.find(',', i);
            const std::string_view rest =
                trimBlanks(line.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i));
            if (!rest.empty()) {
                log.add(Irregularity::TextAfterQuote, lineNo,
                        fmt::format("cell {}: '{}'", cells.size() + 1, rest));
                cell += rest;
            }
            cells.push_back(std::move(cell));
            if (end == std::string_view::npos) break;
            i = end + 1;
        } else {
            const std::size_t end = line.find(',', i);
            cells.emplace_back(
                trimBlanks(line.substr(i, end == std::string_view::npos ? std::string_view::npos : end - i)));
            if (end == std::string_view::npos) break;
            i = end + 1;
        }
    }
    return cells;
}

}  // namespace

bool isCinemaFileColumn(std::string_view name) {
    if (name.substr(0, 4) != "FILE") return false;
    if (name.size() == 4) return true;
    const char c = name[4];
    return c == '_' || (c >= '0' && c <= '9');
}

CsvTable parseCsv(std::string_view text, const std::string& source, const CsvReadOptions& options) {
    CsvTable table;
    table.source = source;
    IrregularityLog log(table.source, options.strict);

    // A UTF-8 byte order mark (spreadsheet exports) is not part of the first name.
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);

    bool haveHeader = false;
    int lineNo = 0;
    std::size_t pos = 0;
    // Short rows are padded to the header's width. A forged file (a header of
    // a million commas, then a million one-cell rows) would turn a few MB into
    // 10^12 cells, so padding is bounded by what the file itself could hold.
    const std::size_t paddingBudget = 4 * text.size() + (std::size_t(1) << 22);
    std::size_t padded = 0;
    while (pos < text.size()) {
        // Lines end in \n, \r\n or a lone \r (old Mac exports): a file of \r
        // line ends is rows, not one header of every cell.
        std::size_t end = text.find_first_of("\r\n", pos);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(pos, end - pos);
        pos = end + 1;
        if (end < text.size() && text[end] == '\r' && pos < text.size() && text[pos] == '\n') ++pos;  // CRLF
        ++lineNo;
        if (trimBlanks(line).empty()) continue;  // blank lines (often the last) carry nothing

        std::vector<std::string> cells = splitLine(line, lineNo, log);
        if (!haveHeader) {
            haveHeader = true;
            std::set<std::string> names;
            for (std::size_t c = 0; c < cells.size(); ++c) {
                if (cells[c].empty())
                    log.add(Irregularity::EmptyColumnName, lineNo, fmt::format("column {}", c + 1));
                else if (!names.insert(cells[c]).second)
                    log.add(Irregularity::DuplicateColumnName, lineNo,
                            fmt::format("'{}' in column {}", cells[c], c + 1));
            }
            table.header = std::move(cells);
            continue;
        }
        const std::size_t n = table.header.size();
        if (cells.size() < n)
            log.add(Irregularity::ShortRow, lineNo, fmt::format("{} of {} cells", cells.size(), n));
        else if (cells.size() > n)
            log.add(Irregularity::LongRow, lineNo, fmt::format("{} of {} cells", cells.size(), n));
        if (cells.size() < n) {
            padded += n - cells.size();
            if (padded > paddingBudget)
                throw InputError(fmt::format("{}:{}: short rows padded to the header's {} columns would add more than "
                                             "{} empty cells to a file of {} bytes; expected rows as wide as the header",
                                             source, lineNo, n, paddingBudget, text.size()));
        }
        cells.resize(n);
        table.rows.push_back(std::move(cells));
        table.rowLines.push_back(lineNo);
    }
    if (!haveHeader)
        throw Error(fmt::format("{}:1: the file is empty; expected a header row naming the columns "
                                "(e.g. 'phi,theta,FILE')",
                                source));
    table.warnings = log.diagnostics();
    return table;
}

CsvTable readCsvFile(const std::string& path, const CsvReadOptions& options) {
    // A FIFO or a device would block or never end: refused by readInputFile.
    return parseCsv(readInputFile(path, "CSV table"), path, options);
}

}  // namespace darkroom
