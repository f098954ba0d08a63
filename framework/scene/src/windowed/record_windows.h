#pragma once
// Fixed-size records of a file, read a window at a time and each window
// decoded by parallel tasks: how the direct mesh readers (binary PLY, legacy
// VTK) fill a surface's arrays without holding the file in memory.
#include "file_range_reader.h"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace darkroom::windowed {

// Records [begin, end) of a window that starts at record `first` of the
// array: record i of the window is record first + i of the array.
struct Span {
    const char* window;
    std::size_t first, begin, end;
};

// Reads `count` records of `recordSize` bytes from `offset`, a window of at
// most `windowBytes` (at least one record) at a time into `buffer`, and
// decodes each window in parallel tasks; false when the file ends early or
// a task's decode fails (the caller then leaves the file to its general reader).
bool readRecords(const FileRangeReader& file, std::uint64_t offset, std::size_t count, std::size_t recordSize,
                 std::size_t windowBytes, std::vector<char>& buffer, const std::function<bool(const Span&)>& decode);

}  // namespace darkroom::windowed
