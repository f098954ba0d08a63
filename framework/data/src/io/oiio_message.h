#pragma once
// OIIO error text as one line (the runner prints one line per error).
#include <string>

namespace darkroom::io {

inline std::string oneLine(std::string text, const char* fallback = "unknown OpenImageIO error") {
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    std::string out;
    for (char c : text) out += c == '\n' ? std::string("; ") : std::string(1, c);
    return out.empty() ? std::string(fallback) : out;
}

}  // namespace darkroom::io
