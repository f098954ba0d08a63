#pragma once
// The tolerant reader of Cinema `data.csv` files. Real databases written by
// ParaView, Ascent, TTK and hand-made scripts differ in small ways (quoted
// numbers, spaces after commas, CRLF, rows of unequal length); this reader
// accepts them all, reports each kind of irregularity once, and turns them into
// errors when asked to be strict.
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>

#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

struct CsvReadOptions {
    // Irregularities (rows shorter or longer than the header, unterminated
    // quotes, text after a closing quote, empty or duplicate column names)
    // become darkroom::Error naming file:line instead of warnings.
    bool strict = false;
};

struct CsvTable {
    std::string source;               // file name used in messages
    std::vector<std::string> header;  // trimmed column names
    // Every row has exactly header.size() cells (short rows padded with "",
    // long rows truncated), trimmed and unquoted.
    std::vector<std::vector<std::string>> rows;
    std::vector<int> rowLines;  // 1-based line of each row in the source
    // One warning per irregularity kind, naming the first line where it occurs
    // and how many times it occurred.
    Diagnostics warnings;
};

// Parses CSV text; `source` names the file in messages. Throws darkroom::Error
// for an empty file (no header) and, when strict, for any irregularity.
DARKROOM_API CsvTable parseCsv(std::string_view text, const std::string& source,
                               const CsvReadOptions& options = {});
// Reads and parses a file; throws darkroom::Error naming it when unreadable.
DARKROOM_API CsvTable readCsvFile(const std::string& path, const CsvReadOptions& options = {});

// Numbers as data.csv holds them: decimal or exponent notation with optional
// sign, and NaN / inf in any letter case. Surrounding spaces must already be
// trimmed. Returns false for anything else (including the empty string).
DARKROOM_API bool parseCsvNumber(std::string_view text, double& out);
// Shortest text that reads back to the same double ("30", "22.5", "1e-07",
// "nan", "inf", "-inf"); negative zero is written "0".
DARKROOM_API std::string formatCsvNumber(double value);
// Quotes a cell when it needs it (comma, quote, surrounding space, line break).
DARKROOM_API std::string quoteCsvCell(std::string_view text);

// FILE columns: "FILE", or "FILE" followed by digits or "_..." ("FILE2", "FILE_png").
DARKROOM_API bool isCinemaFileColumn(std::string_view name);

}  // namespace darkroom
