#pragma once
// The HDF5 module: pycinema's .h5 images (h5_image.h) in a library of its own
// (libdarkroom-h5.so) that the data library opens on first use
// (framework/data/src/io/optional_module.cpp). Debian's HDF5 links libcurl,
// GnuTLS, Kerberos and 33 more libraries, whose loading cost every process
// about 10 ms at start (2-core machine, 29 November); a run that never reads
// or writes .h5 no longer pays it.
#include "h5_image.h"

namespace darkroom::h5_module {

// What the module's one exported symbol returns. `version` comes first and
// changes whenever this struct or the functions' signatures do; the data
// library refuses another.
struct Entry {
    int version;
    h5::Image (*readImageFile)(const std::string& path);
    void (*writeImageFile)(const Buffer& image, const std::string& path, const h5::MetaValues& extra);
};
constexpr int kEntryVersion = 1;
constexpr const char* kEntrySymbol = "darkroom_h5_module";

}  // namespace darkroom::h5_module
