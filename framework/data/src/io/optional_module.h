#pragma once
// Libraries of the data library's own that it opens on first use, beside
// itself (the build tree and the install tree keep them in the same folder):
// the OpenImageIO module (framework/data/oiio/module.h) and the HDF5 module
// (framework/data/h5/module.h). Each brings a heavy dependency that most
// runs never need — OpenImageIO's ~260 shared libraries, HDF5's 36 (libcurl,
// GnuTLS, Kerberos, ...), whose loading and relocation cost every process
// ~10 ms — so a process pays for it only when it meets such a file.
// Internal to the framework.
#include "../../h5/module.h"
#include "../../oiio/module.h"

#include <string>

namespace darkroom::io {

// The modules' functions; throw darkroom::Error saying what `purpose`
// needed the module for (e.g. "reading 'x.tif'") when it cannot be loaded.
const oiio_module::Entry& oiioModule(const std::string& purpose);
const h5_module::Entry& h5Module(const std::string& purpose);

}  // namespace darkroom::io
