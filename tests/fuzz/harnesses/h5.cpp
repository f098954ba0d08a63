// pycinema's .h5 images, read from memory as readCinemaProduct reads a file
// (HDF5's core driver over the bytes; docs/formats.md, "pycinema's HDF5
// images"). HDF5 itself is Debian's, not instrumented: what is checked is our
// walk of the file (links, storage, sizes, types) and what it lets HDF5
// allocate. Properties checked: a buffer read has the size its channels
// declare and finite-or-infinite depth (NaN is converted); and, read or
// refused, every HDF5 object the reader opened is closed again.
//
// HDF5 1.10 itself leaks on some corrupt files (H5Oopen's error path, found
// by this harness): allocations made inside libhdf5 are not reported as
// leaks. Our own handles are what the open-object count checks. HDF5 also
// mallocs sizes a corrupt file declares (a local heap of 2^58 bytes): outside
// a sanitizer that malloc fails and HDF5 reports an error, so here too a
// too-big allocation returns null instead of stopping the run.
#include "harness.h"

#include "h5_image.h"

#include <darkroom/error.h>

#include <hdf5.h>

#include <cmath>

extern "C" const char* __asan_default_options() { return "allocator_may_return_null=1"; }
extern "C" const char* __lsan_default_suppressions() { return "leak:libhdf5_serial.so\nleak:libhdf5.so\n"; }

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const auto image = darkroom::h5::readImage(fuzz::text(data, size), "input.h5");
        fuzz::expect(image.buffer && image.buffer->width() > 0 && image.buffer->height() > 0, "a non-empty image");
        if (const float* z = image.buffer->hostFloat("Z"))
            for (std::size_t i = 0; i < image.buffer->pixelCount(); ++i) fuzz::expect(!std::isnan(z[i]), "no NaN depth");
    } catch (const darkroom::Error&) {
    }
    fuzz::expect(H5Fget_obj_count(H5F_OBJ_ALL, H5F_OBJ_ALL) == 0, "every HDF5 file, group and dataset closed");
    return 0;
}
