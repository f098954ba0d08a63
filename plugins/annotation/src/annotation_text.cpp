#include "annotation_text.h"

#include <darkroom/text/text_limits.h>

#include <darkroom/error.h>
#include <darkroom/data/cinema/row.h>

namespace darkroom::annotation {

namespace {

// The template with each two-character "\n" (typed in the editor's one-line
// field) turned into a line break.
std::string lineBreaks(std::string_view text) {
    std::string lines;
    lines.reserve(text.size());
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '\\' && i + 1 < text.size() && text[i + 1] == 'n') {
            lines += '\n';
            ++i;
        } else {
            lines += text[i];
        }
    }
    return lines;
}

// One placeholder's text ("name" or "name:spec" between the braces), through
// the framework's formatting, with the limits checked first.
std::string fillOne(std::string_view inside, const Row& row, bool markup) {
    const std::size_t colon = inside.find(':');
    if (colon != std::string_view::npos)
        text::checkFormatSpec(inside.substr(colon + 1),
                              "text: placeholder {" + std::string(inside.substr(0, colon)) + "}");
    std::string_view name = inside.substr(0, colon);
    while (!name.empty() && name.back() == ' ') name.remove_suffix(1);
    while (!name.empty() && name.front() == ' ') name.remove_prefix(1);
    for (const auto& [column, cell] : row.cells())
        if (column == name) text::checkTextLength(cell, "text: the value of {" + column + "}");
    const std::string value = fillRowPlaceholders("{" + std::string(inside) + "}", row, "text");
    return markup ? text::escapeMarkup(value) : value;
}

// Throws the framework's error for the template's unbalanced braces (its
// message quotes the whole text, as for any other node).
[[noreturn]] void braceError(const std::string& lines, const Row& row) {
    fillRowPlaceholders(lines, row, "text");
    throw Error("text: unbalanced braces in '" + lines + "'");
}

}  // namespace

std::string expandText(std::string_view text, const Row& row, bool markup) {
    text::checkTextLength(text, "text");
    const std::string lines = lineBreaks(text);
    if (!hasRowPlaceholders(lines)) return fillRowPlaceholders(lines, Row(), "text");  // resolves {{ }}
    if (row.empty())
        throw Error("the text has placeholders but 'row' is empty; connect CinemaReader's row output (or set row "
                    "to e.g. 'time=0.5')");
    // Each placeholder is filled alone, so that its value can be escaped and
    // the growing result bounded; braces follow fillRowPlaceholders.
    std::string out;
    for (std::size_t i = 0; i < lines.size(); ++i) {
        const char c = lines[i];
        const bool doubled = i + 1 < lines.size() && lines[i + 1] == c;
        if ((c == '{' || c == '}') && doubled) {
            out += c;
            ++i;
        } else if (c == '{') {
            const std::size_t close = lines.find('}', i + 1);
            if (close == std::string::npos) braceError(lines, row);
            out += fillOne(std::string_view(lines).substr(i + 1, close - i - 1), row, markup);
            i = close;
        } else if (c == '}') {
            braceError(lines, row);
        } else {
            out += c;
        }
        if (out.size() > text::kMaxTextBytes)
            throw InputError("the text with its placeholders filled grows past " +
                             std::to_string(text::kMaxTextBytes) + " bytes; a node draws at most " +
                             std::to_string(text::kMaxTextBytes) + " bytes of text (docs/publishing.md, text limits)");
    }
    return out;
}

}  // namespace darkroom::annotation
