#include "module.h"

#include <darkroom/export.h>

extern "C" DARKROOM_API const darkroom::h5_module::Entry* darkroom_h5_module() {
    using namespace darkroom;
    static const h5_module::Entry entry{h5_module::kEntryVersion, &h5::readImageFile, &h5::writeImageFile};
    return &entry;
}
