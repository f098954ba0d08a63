#pragma once
// Annotation's text: the two-character "\n" as a line break, placeholders
// filled from the Cinema row, values from data escaped for markup. Pure text
// (the framework's placeholder formatting, no pango), so the fuzz harness
// tests/fuzz/harnesses/annotation.cpp compiles it.
#include <darkroom/row.h>

#include <string>
#include <string_view>

namespace darkroom::annotation {

// The text to draw. Placeholders follow fillRowPlaceholders
// (darkroom/data/cinema/row.h): {column}, {column:spec}, {{ and }}. With
// `markup`, each value substituted from the row is escaped (& < > ' " as
// entities) so that data is shown as text while the template keeps its own
// markup. Throws darkroom::Error for the placeholders' errors (a column the
// row lacks, an empty row when there are placeholders), a
// format width or precision above text::kMaxFormatWidth, a value or a result
// longer than text::kMaxTextBytes (text_limits.h) — before building it.
std::string expandText(std::string_view text, const Row& row, bool markup);

}  // namespace darkroom::annotation
