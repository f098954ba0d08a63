// Decodes a PNG (libpng) and encodes its pixels again as an earlier writer
// did: `libpng-z2` before libdeflate (libpng_encode.h: zlib level 2, "up",
// the same chunks), `libdeflate-l1` before the run encoder (png_encoder.h:
// libdeflate level 1, "up"), `runs` the run encoder the writer uses now (the
// manifest's PNGs since 29 November: a later encoder change checks against it). With the examples' manifest, this shows that a
// new PNG holds the very pixels of the recorded one: same re-encoded bytes,
// same SHA-256 (bench/codecs/check_pngs_against_manifest.sh).
//   png_reencode_before libpng-z2|libdeflate-l1|runs IN.png OUT.png
#include "libpng_encode.h"
#include "png_encoder.h"

#include <png.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

int main(int argc, char** argv) {
    const std::string as = argc == 4 ? argv[1] : "";
    if (as != "libpng-z2" && as != "libdeflate-l1" && as != "runs") {
        std::fprintf(stderr, "usage: %s libpng-z2|libdeflate-l1|runs IN.png OUT.png\n", argv[0]);
        return 2;
    }
    ++argv;
    std::ifstream in(argv[1], std::ios::binary);
    const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_memory(&image, file.data(), file.size())) {
        std::fprintf(stderr, "%s: %s\n", argv[1], image.message);
        return 1;
    }
    // The file's own 8-bit layout: no conversion.
    const int channels = int(PNG_IMAGE_SAMPLE_CHANNELS(image.format));
    if (image.format & PNG_FORMAT_FLAG_LINEAR) {
        std::fprintf(stderr, "%s: not an 8-bit PNG\n", argv[1]);
        return 1;
    }
    std::vector<unsigned char> pixels(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, pixels.data(), 0, nullptr)) {
        std::fprintf(stderr, "%s: %s\n", argv[1], image.message);
        return 1;
    }
    const int w = int(image.width), h = int(image.height);
    using darkroom::io::Deflater;
    using darkroom::io::PngFilter;
    const std::string png =
        as == "libpng-z2"
            ? darkroom::bench::libpngEncode(pixels.data(), w, h, channels, 2, PNG_FILTER_UP)
            : darkroom::io::encodePng({w, h, channels, pixels.data()},
                                      {PngFilter::Up, 1, as == "runs" ? Deflater::Runs : Deflater::Libdeflate});
    std::ofstream(argv[2], std::ios::binary).write(png.data(), std::streamsize(png.size()));
    return 0;
}
