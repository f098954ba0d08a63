#include "legacy_lines.h"

#include <darkroom/data/formats/text_cursor.h>

#include <algorithm>
#include <string_view>

namespace darkroom::vtk_legacy {
namespace {

// Keyword lines are short (a title is at most 256 characters): a line
// longer than this is left to the general reader.
constexpr std::size_t kWindow = 4096;

// What TextCursor::atEnd() skips.
bool isSpace(char c) { return c == '\n' || c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

}  // namespace

std::optional<Line> lineAt(const windowed::FileRangeReader& file, std::uint64_t offset, bool skipSpace) {
    if (offset > file.size()) return std::nullopt;
    const std::size_t n = std::size_t(std::min<std::uint64_t>(kWindow, file.size() - offset));
    const bool toEnd = offset + n == file.size();
    std::string window(n, '\0');
    if (!file.read(offset, n, window.data())) return std::nullopt;
    std::size_t pos = 0;
    Line line;
    if (skipSpace) {
        while (pos < n && isSpace(window[pos])) ++pos;
        if (pos == n) {
            if (!toEnd) return std::nullopt;
            line.atEnd = true;
            line.end = file.size();
            return line;
        }
    }
    const std::size_t newline = window.find('\n', pos);
    const std::size_t stop = newline == std::string::npos ? n : newline;
    line.text = window.substr(pos, stop - pos);
    line.complete = newline != std::string::npos || toEnd;
    line.end = offset + (newline == std::string::npos ? n : newline + 1);
    std::string_view whole = line.text;
    if (!line.complete) {
        // The last token may go on past the window: keep only those that end in it.
        const std::size_t blank = whole.find_last_of(" \t\r");
        whole = blank == std::string_view::npos ? std::string_view() : whole.substr(0, blank);
    }
    for (std::string_view t : mesh::splitBlanks(whole)) line.tokens.emplace_back(t);
    return line;
}

std::optional<bool> startsWith(const Line& line, std::string_view keyword) {
    std::string_view token = line.text;
    const std::size_t begin = token.find_first_not_of(" \t\r");
    if (begin == std::string_view::npos) {
        if (!line.complete) return std::nullopt;
        return false;
    }
    token.remove_prefix(begin);
    const std::size_t end = token.find_first_of(" \t\r");
    const bool whole = end != std::string_view::npos || line.complete;
    token = token.substr(0, end);
    if (whole) return token == keyword;
    // The window cut the token (binary data, as a rule): it can be the
    // keyword only if it begins the keyword.
    if (token.size() > keyword.size() || keyword.substr(0, token.size()) != token) return false;
    return std::nullopt;
}

}  // namespace darkroom::vtk_legacy
