// Annotation's text (plugins/annotation): the template's placeholders filled
// from a row, with and without markup escaping. The input is text: a first
// character 'm' asks for markup (any other for plain text), the rest of the
// first line is the row ("time=0.5, name=R&D"), the lines after it the
// template. Beyond not crashing: the result stays within the
// text limit, and with markup every value's & < > ' " arrive as entities —
// checked by expanding a template that has no markup of its own and finding
// no raw '<' or '>' in the result.
#include "harness.h"

#include "annotation_text.h"
#include <darkroom/text/text_limits.h>

#include <darkroom/error.h>
#include <darkroom/row.h>

#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size == 0) return 0;
    const bool markup = data[0] == 'm';
    const std::string input(fuzz::text(data + 1, size - 1));
    const std::size_t newline = input.find('\n');
    const std::string row = input.substr(0, newline);
    const std::string text = newline == std::string::npos ? "" : input.substr(newline + 1);
    try {
        const std::string out = darkroom::annotation::expandText(text, darkroom::parseRow(row), markup);
        fuzz::expect(out.size() <= darkroom::text::kMaxTextBytes, "the text is within the limit");
        if (markup && text.find_first_of("<>&'\"") == std::string::npos) {
            fuzz::expect(out.find_first_of("<>'\"") == std::string::npos, "values are escaped");
            for (std::size_t i = out.find('&'); i != std::string::npos; i = out.find('&', i + 1)) {
                const std::string_view rest = std::string_view(out).substr(i);
                fuzz::expect(rest.starts_with("&amp;") || rest.starts_with("&lt;") || rest.starts_with("&gt;") ||
                                 rest.starts_with("&apos;") || rest.starts_with("&quot;"),
                             "every & of a value starts an entity");
            }
        }
    } catch (const darkroom::Error&) {
    }
    return 0;
}
