#pragma once
// A regular file read by byte ranges (pread), so that a big mesh is decoded
// a window at a time instead of being held in memory whole.
#include <cstddef>
#include <cstdint>
#include <string>

namespace darkroom::windowed {

class FileRangeReader {
public:
    // Opens `path` if it is a regular file; otherwise ok() is false (the
    // caller's fallback, the whole-file reader, says why).
    explicit FileRangeReader(const std::string& path);
    ~FileRangeReader();
    FileRangeReader(const FileRangeReader&) = delete;
    FileRangeReader& operator=(const FileRangeReader&) = delete;

    bool ok() const { return fd_ >= 0; }
    std::uint64_t size() const { return size_; }
    // Reads bytes [offset, offset + n) into `out`; false if the file ends
    // first (it shrank since it was opened) or the read fails.
    bool read(std::uint64_t offset, std::size_t n, char* out) const;

private:
    int fd_ = -1;
    std::uint64_t size_ = 0;
};

}  // namespace darkroom::windowed
