#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

namespace darkroom {

namespace {

const char* kindOf(mode_t mode) {
    if (S_ISDIR(mode)) return "a directory";
    if (S_ISFIFO(mode)) return "a FIFO";
    if (S_ISCHR(mode)) return "a character device";
    if (S_ISBLK(mode)) return "a block device";
    if (S_ISSOCK(mode)) return "a socket";
    return "not a regular file";
}

}  // namespace

std::uint64_t requireRegularFile(const std::string& path, const std::string& what) {
    // Opened, not only stat()ed: a file we may not read (permission denied)
    // is bad input here, as in readInputFile, not a library's failure later.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw InputError("cannot read " + what + " '" + path + "': " + std::strerror(errno));
    struct stat st {};
    const bool ok = ::fstat(fd, &st) == 0;
    const int err = errno;
    ::close(fd);
    if (!ok) throw InputError("cannot read " + what + " '" + path + "': " + std::strerror(err));
    if (!S_ISREG(st.st_mode))
        throw InputError("cannot read " + what + " '" + path + "': it is " + kindOf(st.st_mode) +
                         "; expected a regular file");
    return std::uint64_t(st.st_size);
}

std::string readInputFile(const std::string& path, const std::string& what) {
    // Opened first, then checked through the descriptor: the name cannot be
    // swapped for a FIFO between the check and the read. O_NONBLOCK keeps the
    // open of a FIFO from waiting for a writer.
    const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) throw InputError("cannot read " + what + " '" + path + "': " + std::strerror(errno));
    struct stat st {};
    if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        ::close(fd);
        throw InputError("cannot read " + what + " '" + path + "': it is " + kindOf(st.st_mode) +
                         "; expected a regular file");
    }
    try {
        checkBytes(Limit::InputBytes, std::uint64_t(st.st_size), path, what);
    } catch (...) {
        ::close(fd);
        throw;
    }
    std::string bytes(std::size_t(st.st_size), '\0');
    std::size_t done = 0;
    // A file that grows while read is read up to its size at open.
    while (done < bytes.size()) {
        const ssize_t n = ::read(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            throw InputError("cannot read " + what + " '" + path + "': " + why);
        }
        if (n == 0) break;  // shrank while read
        done += std::size_t(n);
    }
    ::close(fd);
    bytes.resize(done);
    return bytes;
}

}  // namespace darkroom
