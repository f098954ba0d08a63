#pragma once
// The text lines of a binary legacy VTK file (its header and the keyword
// lines between its arrays), read from a byte offset through a small
// window, split as the general reader's TextCursor splits them, so that the
// direct reader takes a file only where the general one reads it the same way.
#include "../windowed/file_range_reader.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom::vtk_legacy {

struct Line {
    std::string text;                 // as far as the window holds it, without its newline
    std::vector<std::string> tokens;  // blank-separated (mesh::splitBlanks)
    std::uint64_t end = 0;            // just past its newline, or the file's end
    bool atEnd = false;               // only whitespace was left: no line
    bool complete = true;             // false: the window ended inside it; `tokens` are those it holds whole
};

// The line that starts at `offset`, after the whitespace TextCursor::atEnd()
// skips when `skipSpace` (the general reader's keyword loop skips it; its
// look-aheads, such as the one for OFFSETS, do not). Nothing when the
// window holds only whitespace short of the file's end, or the read fails.
std::optional<Line> lineAt(const windowed::FileRangeReader& file, std::uint64_t offset, bool skipSpace);

// Whether the first token of `line` is `keyword`, as the general reader's
// look-aheads ask of the line that follows POLYGONS or SCALARS (binary data,
// as a rule, which may run far past the window before a newline): nothing
// only when the window cut a token that begins the keyword.
std::optional<bool> startsWith(const Line& line, std::string_view keyword);

}  // namespace darkroom::vtk_legacy
