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

#include <ImfHeader.h>

#include <string>

namespace darkroom::io {

// Decodes the pixels of `path` into `buffer` and returns true when the file is
// a single-part scan-line image, compressed with NONE, ZIPS or ZIP, whose
// channels are UINT, HALF or FLOAT without subsampling, written in increasing
// y, into a buffer laid out as readExr lays it out: the data window's size,
// buffer pixel (0, 0) at the window's top-left corner, rows in increasing y,
// one plane per file channel (UINT in UInt32, HALF widened to float as
// OpenEXR widens it, FLOAT as stored). `header` is the header as OpenEXR's
// C++ library read it, from which readExr sized the buffer; the Core API's
// reading of the same header must agree with it on every point above (a
// damaged header can read differently: a missing compression attribute is
// ZIP to one and NONE to the other). Returns false for any other file and
// for anything inconsistent (a size, an offset, a stream that does not
// inflate to exactly its size): the planes then hold anything, and the caller
// reads with the C++ library, which decodes every pixel again or words the
// error.
bool readExrDirect(const std::string& path, const Imf::Header& header, WritableBuffer& buffer);

}  // namespace darkroom::io
