#include "module.h"

#include <darkroom/export.h>

extern "C" DARKROOM_API const darkroom::oiio_module::Entry* darkroom_oiio_module() {
    using namespace darkroom::oiio_module;
    static const Entry entry{kEntryVersion, &readImage, &readHeader, &writeImage};
    return &entry;
}
