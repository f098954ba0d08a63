#pragma once
// One entry of a table as it travels through the graph: a Cinema database's
// row (CinemaReader's `row` output), read by the nodes that need the entry
// being shaded (Annotation's text, CinemaWriter's columns, Spheres' point
// list) without parsing text. Cells are named and in column order; a cell
// keeps its text as written in the table, so a number keeps its spelling
// ("0.50" stays "0.50") and an entry written from it reads back the same.
//
// Its text form, for pipeline files, `--set` and a row typed by hand, is the
// reader's query syntax:
//
//   time=0.5, phi=30, FILE=/abs/db.cdb/time=0.5_phi=30.exr
//
// a value holding ',', '=' or '"' (or leading or trailing blanks) quoted,
// "" standing for a quote.
#include <darkroom/export.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace darkroom {

struct RowCell {
    std::string column;
    std::string text;
    bool operator==(const RowCell&) const = default;
};

class DARKROOM_API Row {
public:
    Row() = default;
    // Throws darkroom::Error naming the column when one is given twice.
    explicit Row(std::vector<RowCell> cells);

    const std::vector<RowCell>& cells() const { return cells_; }
    bool empty() const { return cells_.empty(); }
    // The cell of `column` as written, or nullptr when the row has no such column.
    const std::string* find(std::string_view column) const;
    // "time, phi, FILE" (or "none"): for messages naming what a row offers.
    std::string columnNames() const;

    bool operator==(const Row&) const = default;

private:
    std::vector<RowCell> cells_;
};

// "name=value, ..." items as written, duplicates kept: the syntax shared by a
// row's text and CinemaReader's `parameters`. Throws darkroom::Error naming
// `what` and the text on an unterminated quote or an item without '='.
DARKROOM_API std::vector<RowCell> parseNameValues(std::string_view text, std::string_view what);

// The text form above, and back; parseRow throws darkroom::Error on bad
// syntax or a column given twice.
DARKROOM_API std::string formatRow(const Row& row);
DARKROOM_API Row parseRow(std::string_view text);

}  // namespace darkroom
