#pragma once
// Base64 as VTK XML writes it: the header and the data are often encoded as
// separate padded streams back to back, so decoding goes quantum by quantum
// (4 characters at a time, padding allowed in any quantum) instead of
// treating '=' as the end of everything.
#include <darkroom/export.h>

#include <cstddef>
#include <string>
#include <string_view>

namespace darkroom::mesh {

class DARKROOM_API Base64Stream {
public:
    explicit Base64Stream(std::string_view text) : text_(text) {}
    // Appends the next n decoded bytes to out. Returns false with `error` set
    // on a bad character or when the text ends first.
    bool read(std::size_t n, std::string& out, std::string& error);

private:
    bool quantum(std::string& error);
    std::string_view text_;
    std::size_t pos_ = 0;
    std::string pending_;
};

}  // namespace darkroom::mesh
