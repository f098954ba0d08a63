#pragma once
// A failing disk without root or strace: while a FileSizeLimit lives, this
// process (and every process it starts) cannot grow a file past `bytes`;
// such a write fails with EFBIG (SIGXFSZ is ignored), as one on a full
// quota or a failing network file system fails with its own errno.
#include <csignal>
#include <cstddef>
#include <sys/resource.h>

namespace darkroom::test {

class FileSizeLimit {
public:
    explicit FileSizeLimit(std::size_t bytes);
    ~FileSizeLimit();
    FileSizeLimit(const FileSizeLimit&) = delete;
    FileSizeLimit& operator=(const FileSizeLimit&) = delete;

private:
    rlimit saved_{};
    struct sigaction savedAction_ {};
};

}  // namespace darkroom::test
