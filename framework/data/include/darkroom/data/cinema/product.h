#pragma once
// One product file of a Cinema database as a Darkroom buffer, whatever wrote it.
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>

#include <memory>
#include <string>

namespace darkroom {

// By extension:
// - .npz: one float32 channel per member, named after it ("data"); members
//   must be 2-D (rows, columns) arrays of one size, rows top to bottom as
//   stored. A 3-D (rows, columns, k) member gives channels "name.0".."name.k-1".
// - .vti: VTK XML ImageData (TTK CinemaImaging), see formats/vti.h.
// - anything else: readImage (PNG, JPEG, TIFF, EXR, ...).
// Conversions worth knowing are appended to `warnings` when given.
// Throws darkroom::Error naming the file.
DARKROOM_API std::shared_ptr<WritableBuffer> readCinemaProduct(const std::string& path,
                                                               Diagnostics* warnings = nullptr);

}  // namespace darkroom
