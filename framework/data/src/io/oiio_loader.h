#pragma once
// Opens the OpenImageIO module (framework/data/oiio/module.h) on first use: the
// library beside libdarkroom-framework.so. Internal to the framework.
#include "../../oiio/module.h"

namespace darkroom::io {

// The module's functions; throws darkroom::Error saying what `purpose`
// needed it (e.g. "reading 'x.tif'") when it cannot be loaded.
const oiio_module::Entry& oiioModule(const std::string& purpose);

}  // namespace darkroom::io
