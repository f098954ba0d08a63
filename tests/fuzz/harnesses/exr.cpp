// The framework's native OpenEXR reader (framework/data/src/io/exr_file.cpp):
// header only (darkroom info), then pixels, through the direct decoder where
// it takes the file (exr_direct.h) and through OpenEXR's C++ library alone.
// OpenEXR itself is not instrumented; what is checked is Darkroom's use of it,
// and that the two decoders agree: when the direct decoder takes an input the
// C++ library reads, their pixels must be the same bit for bit, or the harness
// aborts. (Only then: on some damaged files the C++ library leaves samples
// unwritten, so two of its reads need not agree.)
#include "harness.h"
#include "io/exr_direct.h"
#include "io/exr_file.h"

#include <darkroom/error.h>

#include <ImfInputFile.h>

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

// The direct decoder's pixels, when it takes the file, into a buffer laid out
// as `reference`'s; null otherwise.
std::shared_ptr<darkroom::WritableBuffer> decodeDirect(const std::string& path, const darkroom::Buffer& reference) {
    try {
        const Imf::InputFile file(path.c_str(), 1);
        auto buffer = darkroom::makeCpuBuffer(reference.width(), reference.height(), reference.channels());
        return darkroom::io::readExrDirect(path, file.header(), *buffer) ? buffer : nullptr;
    } catch (const std::exception&) {
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
    (void)readOrNull(path, darkroom::io::ExrPixelPath::DirectWhenPossible);  // what readImage does
    const auto openExr = readOrNull(path, darkroom::io::ExrPixelPath::OpenExrOnly);
    if (!openExr) return 0;
    const auto direct = decodeDirect(path, *openExr);
    if (direct && !samePixels(*direct, *openExr)) {
        std::fprintf(stderr, "the direct EXR decoder and OpenEXR's C++ library read different pixels\n");
        std::abort();
    }
    return 0;
}
