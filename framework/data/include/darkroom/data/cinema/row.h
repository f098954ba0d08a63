#pragma once
// One row of a Cinema database as it travels through the graph: a String value
// port (CinemaReader's `row` output) read by the nodes that need the entry
// being shaded (Annotation's text, CinemaWriter's columns, Spheres' point
// list). The text is the query syntax CinemaReader's `parameters` takes:
//
//   time=0.5, phi=30, theta=45, FILE=/abs/db.cdb/time=0.5_phi=30_theta=45.exr
//
// parameter columns as written in data.csv, then FILE columns as absolute
// product paths; a value holding ',', '=' or '"' (or leading or trailing
// spaces) is quoted, "" standing for a quote. Being plain text, it can be typed
// into the port by hand when no reader is connected.
#include <darkroom/export.h>

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace darkroom {

class CinemaDatabase;

// Column name and cell text, in column order.
using CinemaRow = std::vector<std::pair<std::string, std::string>>;

// The row text of `row`: parameters as written, FILE columns as absolute paths
// of the products (empty cells stay empty).
DARKROOM_API std::string cinemaRowText(const CinemaDatabase& db, std::size_t row);

// "a=1, b=x" from cells, quoting values as described above.
DARKROOM_API std::string formatCinemaRow(const CinemaRow& row);

// Parses row text; throws darkroom::Error on bad syntax or a column given twice.
DARKROOM_API CinemaRow parseCinemaRow(std::string_view text);

// Replaces placeholders in `pattern` with the row's values, as Python's
// str.format does: "{time}" is the cell as written; "{time:.2f}" formats it
// as a number with that specification (fmt / Python format-spec syntax: fill,
// align, sign, width, precision, type); "{{" and "}}" are literal braces.
// Throws darkroom::Error naming `what`, the placeholder and the row's columns
// when a column is missing, a number format meets text, or braces are unbalanced.
DARKROOM_API std::string fillRowPlaceholders(std::string_view pattern, const CinemaRow& row,
                                             std::string_view what);

// True when `pattern` holds at least one {placeholder} (not counting {{ }}).
DARKROOM_API bool hasRowPlaceholders(std::string_view pattern);

}  // namespace darkroom
