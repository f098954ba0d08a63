#pragma once
// One product file of a Cinema database as a Darkroom buffer, whatever wrote it.
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>

#include <memory>
#include <optional>
#include <string>

namespace darkroom {

// By extension:
// - .npz: one float32 channel per member, named after it ("data"); members
//   must be 2-D (rows, columns) arrays of one size, rows top to bottom as
//   stored. A 3-D (rows, columns, k) member gives channels "name.0".."name.k-1".
// - .vti: VTK XML ImageData (TTK CinemaImaging), see formats/vti.h.
// - .h5: pycinema's (and ParaView's Cinema plugin's) HDF5 images, groups
//   channels and meta (docs/formats.md, "pycinema's HDF5 images").
// - anything else: readImage (PNG, JPEG, TIFF, EXR, ...).
// Conversions worth knowing are appended to `warnings` when given.
// Throws darkroom::Error naming the file; InputError with geometryProduct's
// advice for a mesh or a volume (a 3-D .vti, .vtk, .vtu, .vtp).
DARKROOM_API std::shared_ptr<WritableBuffer> readCinemaProduct(const std::string& path,
                                                               Diagnostics* warnings = nullptr);

// Whether the extension is a VTK dataset's (.vti .vtk .vtu .vtp .pvtu
// .pvtp): only a 2-D .vti among them is an image.
DARKROOM_API bool isVtkProduct(const std::string& path);

// A product that is a mesh or a volume rather than an image: Darkroom shades
// images, and geometry becomes images through a capture (docs/scene-format.md).
struct GeometryProduct {
    std::string what;    // "a volume (VTK ImageData of 2 x 2 x 2 points)"
    std::string advice;  // what to do instead: capture it, or convert it first
};

// What `path` is when it is geometry; nullopt for anything else (a 2-D .vti,
// pictures, arrays). Reads a .vti's markup and a legacy .vtk's header;
// throws darkroom::Error when those cannot be read.
DARKROOM_API std::optional<GeometryProduct> geometryProduct(const std::string& path);

}  // namespace darkroom
