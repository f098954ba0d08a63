#pragma once
// A direct decoder for the EXR files Darkroom reads most: those `darkroom
// capture` and CinemaWriter write (one part, scan lines, ZIP, FLOAT). OpenEXR
// 3.1's C++ library spends most of such a read copying sample by sample into
// the frame buffer, and inflates with zlib; here OpenEXR's Core C API reads the
// raw chunks (documented as safe from several threads), libdeflate inflates
// them, the zip pre-pass is undone (exr_zip.h) and each line goes straight into
// its planes, chunks in parallel with TBB (docs/performance.md, "EXR reading").
// Internal to the data library; readExr (exr_file.h) calls it and falls back to
// the C++ library for everything else.
#include <darkroom/buffer.h>

#include <string>

namespace darkroom::io {

// The data window as readExr lays it out: buffer pixel (0, 0) is the file's
// pixel (x0, y0), rows top to bottom in increasing y, as OpenEXR's are.
struct ExrWindow {
    int x0 = 0, y0 = 0, width = 0, height = 0;
};

// Decodes the pixels of `path` into `buffer` and returns true when the file is
// a single-part scan-line image, compressed with NONE, ZIPS or ZIP, whose
// channels are UINT, HALF or FLOAT without subsampling, written in increasing
// y, with `window` as its data window and exactly `buffer`'s channels (UINT in
// UInt32 planes, HALF widened to float as OpenEXR widens it, FLOAT as stored).
// Returns false for any other file and for anything inconsistent (a size,
// an offset, a stream that does not inflate to exactly its size): the planes
// then hold anything, and the caller reads with OpenEXR's C++ library, which
// decodes every pixel again or words the error.
bool readExrDirect(const std::string& path, const ExrWindow& window, WritableBuffer& buffer);

}  // namespace darkroom::io
