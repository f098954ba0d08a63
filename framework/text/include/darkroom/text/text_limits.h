#pragma once
// What text an overlay node may produce and how values from data enter
// markup. Pure string work (no pango, no cairo), so the fuzz harnesses
// (tests/fuzz) compile it as it is.
//
// Why bounds: a format width such as {phi:>200000000} or a 20 MB cell of
// data.csv once made a node build gigabytes of text and pango abort the
// process (issue 26). Every text a node draws and every format specification
// it applies is checked against these limits first, and refused with an
// error naming what asked for it and the limit.
#include <cstddef>
#include <string>
#include <string_view>

namespace darkroom::text {

// The largest width or precision a format specification may ask for
// ({time:>12.3f}, labelFormat .4e): far wider than any label, far below
// anything costly.
inline constexpr std::size_t kMaxFormatWidth = 1000;

// The most bytes of text one node draws (after placeholders are filled), and
// so the most a single value from data may hold.
inline constexpr std::size_t kMaxTextBytes = 64 * 1024;

// Throws darkroom::Error "<what>: format '<spec>' asks for a width or
// precision of N; at most 1000 are allowed" when a number in `spec` (the part
// after ':' of a placeholder) is above kMaxFormatWidth. Every run of digits
// is counted: in fmt's grammar they are widths and precisions (and a digit
// used as fill, which is one digit).
void checkFormatSpec(std::string_view spec, std::string_view what);

// Throws darkroom::Error "<what> is N bytes long; a node draws at most 65536
// bytes of text" when `text` is longer than kMaxTextBytes.
void checkTextLength(std::string_view text, std::string_view what);

// Text as Pango markup that shows it literally: & < > ' " become entities
// (what g_markup_escape_text does for these characters).
std::string escapeMarkup(std::string_view text);

}  // namespace darkroom::text
