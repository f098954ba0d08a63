#pragma once
// NumPy arrays: `.npy` files and `.npz` archives (a zip of `.npy` members), as
// written by numpy.save / numpy.savez(_compressed). Composable image sets from
// TTK, Ascent and ParaView store one image channel per `.npz`.
//
// Every array is converted to float32 in C (row-major) order on reading:
// float64, int32/int64/uint32 above 2^24 and uint64 lose precision (float32
// has a 24-bit significand); int8/uint8/int16/uint16/bool and float32 are exact.
#include <darkroom/export.h>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace darkroom {

struct NpyArray {
    std::string name;                // member name without ".npy" ("data"); "" for a lone .npy
    std::string descr;               // dtype as written: "<f4", ">i4", "|u1"
    std::vector<std::size_t> shape;  // as written; () is a scalar (one value)
    bool fortranOrder = false;       // as written; values below are always C order
    std::vector<float> values;       // product(shape) values, C (row-major) order

    std::size_t count() const;
};

// The header of a .npy image without its data (for `darkroom info`).
struct NpyHeader {
    std::string descr;
    std::vector<std::size_t> shape;
    bool fortranOrder = false;
    std::size_t dataOffset = 0;  // bytes before the first value
    std::size_t dataBytes = 0;   // bytes of the values: product(shape) x dtype size
};

// Parses the magic, version (1, 2 or 3) and header dict of .npy bytes. `where`
// names the file (and member) in messages: "x.npz:data.npy". Throws
// darkroom::Error for a bad magic, version, header or an unsupported dtype, and
// InputError for a shape whose size overflows.
DARKROOM_API NpyHeader parseNpyHeader(std::string_view bytes, const std::string& where);
// Parses a whole .npy image; throws darkroom::Error naming `where` when the
// data is shorter than the header's shape requires.
DARKROOM_API NpyArray parseNpy(std::string_view bytes, const std::string& where);

// Reads every .npy member of an .npz archive (stored or deflated), in archive
// order. Throws darkroom::Error naming the file (and member) when the archive
// or a member is malformed; InputError before reading a member whose size in
// the zip directory differs from what its header's shape needs, or exceeds
// limit(Limit::DecodedBytes).
DARKROOM_API std::vector<NpyArray> readNpz(const std::string& path);
// Only the headers (name, dtype, shape) of each member, without converting data.
DARKROOM_API std::vector<NpyArray> readNpzHeaders(const std::string& path);

// Writes an .npz (numpy.savez layout: "<name>.npy" members, little-endian
// float32, version 1.0 headers), deflated when `compress`; atomically.
DARKROOM_API void writeNpz(const std::string& path, const std::vector<NpyArray>& arrays,
                           bool compress = false);
// The .npy bytes of one array as float32 ("<f4"); `values` are in C order and are
// stored in Fortran order (header fortran_order True) when `fortranOrder` is set.
DARKROOM_API std::string encodeNpy(const NpyArray& array);

}  // namespace darkroom
