// pycinema's .h5 images, read from memory as readCinemaProduct reads a file
// (HDF5's core driver over the bytes; docs/formats.md, "pycinema's HDF5
// images"). HDF5 itself is Debian's, not instrumented: what is checked is our
// walk of the file (links, storage, sizes, types) and what it lets HDF5
// allocate. Property checked: a buffer read has the size its channels declare
// and finite-or-infinite depth (NaN is converted).
#include "harness.h"

#include "formats/h5_image.h"

#include <darkroom/error.h>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto image = darkroom::h5::readImage(fuzz::text(data, size), "input.h5");
        fuzz::expect(image.buffer && image.buffer->width() > 0 && image.buffer->height() > 0, "a non-empty image");
        if (const float* z = image.buffer->hostFloat("Z"))
            for (std::size_t i = 0; i < image.buffer->pixelCount(); ++i) fuzz::expect(!std::isnan(z[i]), "no NaN depth");
    } catch (const darkroom::Error&) {
    }
    return 0;
}
