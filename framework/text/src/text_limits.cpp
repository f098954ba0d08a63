#include <darkroom/text/text_limits.h>

#include <darkroom/error.h>

namespace darkroom::text {

namespace {

// At most the first 40 bytes of something quoted in an error (the whole of
// a long specification would drown the message).
std::string shown(std::string_view s) {
    return s.size() <= 40 ? std::string(s) : std::string(s.substr(0, 40)) + "...";
}

}  // namespace

void checkFormatSpec(std::string_view spec, std::string_view what) {
    for (std::size_t i = 0; i < spec.size();) {
        if (spec[i] < '0' || spec[i] > '9') {
            ++i;
            continue;
        }
        // Saturating: a run of a thousand digits is just "too large".
        std::size_t value = 0;
        const std::size_t start = i;
        for (; i < spec.size() && spec[i] >= '0' && spec[i] <= '9'; ++i)
            value = value > kMaxFormatWidth ? value : value * 10 + std::size_t(spec[i] - '0');
        if (value > kMaxFormatWidth)
            throw InputError(std::string(what) + ": format '" + shown(spec) +
                             "' asks for a width or precision of " + shown(spec.substr(start, i - start)) +
                             "; at most " + std::to_string(kMaxFormatWidth) +
                             " are allowed (docs/publishing.md, text limits)");
    }
}

void checkTextLength(std::string_view text, std::string_view what) {
    if (text.size() > kMaxTextBytes)
        throw InputError(std::string(what) + " is " + std::to_string(text.size()) +
                         " bytes long; a node draws at most " + std::to_string(kMaxTextBytes) +
                         " bytes of text (docs/publishing.md, text limits)");
}

std::string escapeMarkup(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (const char c : text) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '\'': out += "&apos;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace darkroom::text
