#pragma once
// A Cinema database's row as a typed row value (darkroom/row.h), and the
// {column} placeholders that nodes fill from it (Annotation's text,
// Spheres' point-list path).
#include <darkroom/export.h>
#include <darkroom/row.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace darkroom {

class CinemaDatabase;

// Row `row` of the database: parameter columns as written, then FILE columns
// as the absolute paths of the products (empty cells stay empty).
DARKROOM_API Row cinemaRow(const CinemaDatabase& db, std::size_t row);
// Replaces placeholders in `pattern` with the row's values, as Python's
// str.format does: "{time}" is the cell as written; "{time:.2f}" formats it
// as a number with that specification (fmt / Python format-spec syntax: fill,
// align, sign, width, precision, type); "{{" and "}}" are literal braces.
// Throws darkroom::Error naming `what`, the placeholder and the row's columns
// when a column is missing, a number format meets text, or braces are unbalanced.
DARKROOM_API std::string fillRowPlaceholders(std::string_view pattern, const Row& row,
                                             std::string_view what);

// True when `pattern` holds at least one {placeholder} (not counting {{ }}).
DARKROOM_API bool hasRowPlaceholders(std::string_view pattern);

}  // namespace darkroom
