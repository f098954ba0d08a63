#include "label_format.h"

#include <darkroom/text/text_limits.h>

#include <darkroom/error.h>

#include <fmt/format.h>

#include <string_view>

namespace darkroom::legend {

void applyLabelFormat(std::vector<Tick>& ticks, const std::string& spec) {
    const std::string what = "labelFormat '" + spec.substr(0, 40) + (spec.size() > 40 ? "...'" : "'");
    // A brace would end the replacement field and let the specification
    // write text of its own around the number.
    if (spec.find_first_of("{}") != std::string::npos)
        throw InputError(what + ": braces are not part of a format specification; expected e.g. .2f, .1e or g");
    text::checkFormatSpec(spec, "labelFormat");
    // fmt does not reject every unknown presentation type; these are its float ones.
    const char type = spec.back();
    if (((type >= 'a' && type <= 'z') || (type >= 'A' && type <= 'Z')) &&
        std::string_view("aAeEfFgG").find(type) == std::string_view::npos)
        throw Error(what + ": unknown type '" + std::string(1, type) + "'; expected e.g. .2f, .1e or g");
    for (auto& t : ticks) {
        try {
            t.label = fmt::format(fmt::runtime("{:" + spec + "}"), t.value);
        } catch (const fmt::format_error& e) {
            throw Error(what + " cannot format a number (" + e.what() + "); expected e.g. .2f, .1e or g");
        }
    }
}

}  // namespace darkroom::legend
