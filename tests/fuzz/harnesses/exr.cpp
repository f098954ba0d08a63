// The framework's native OpenEXR reader (framework/data/src/io/exr_file.cpp):
// header only (darkroom info), then pixels, through the direct decoder where
// it takes the file (exr_direct.h) and through OpenEXR's C++ library alone.
// OpenEXR itself is not instrumented; what is checked is Darkroom's use of it,
// and that the two decoders agree: when both read an input, their pixels must
// be the same bit for bit, or the harness aborts.
#include "harness.h"
#include "io/exr_file.h"

#include <darkroom/error.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>

namespace {

bool samePixels(const darkroom::Buffer& a, const darkroom::Buffer& b) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels().size() != b.channels().size()) return false;
    for (std::size_t c = 0; c < a.channels().size(); ++c) {
        const auto& ch = a.channels()[c];
        if (ch.name != b.channels()[c].name || ch.type != b.channels()[c].type) return false;
        const void* pa = ch.type == darkroom::ChannelType::UInt32 ? static_cast<const void*>(a.hostUInt(ch.name))
                                                                   : static_cast<const void*>(a.hostFloat(ch.name));
        const void* pb = ch.type == darkroom::ChannelType::UInt32 ? static_cast<const void*>(b.hostUInt(ch.name))
                                                                   : static_cast<const void*>(b.hostFloat(ch.name));
        if (std::memcmp(pa, pb, a.pixelCount() * 4) != 0) return false;
    }
    return true;
}

std::shared_ptr<darkroom::WritableBuffer> readOrNull(const std::string& path, darkroom::io::ExrPixelPath pixels) {
    try {
        return darkroom::io::readExr(path, pixels);
    } catch (const darkroom::Error&) {
        return nullptr;
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string path = fuzz::writeInput(data, size, "input.exr");
    try {
        (void)darkroom::io::readExrHeader(path);
    } catch (const darkroom::Error&) {
    }
    const auto direct = readOrNull(path, darkroom::io::ExrPixelPath::DirectWhenPossible);
    const auto openExr = readOrNull(path, darkroom::io::ExrPixelPath::OpenExrOnly);
    if (direct && openExr && !samePixels(*direct, *openExr)) {
        std::fprintf(stderr, "the direct EXR decoder and OpenEXR's C++ library read different pixels\n");
        std::abort();
    }
    return 0;
}
