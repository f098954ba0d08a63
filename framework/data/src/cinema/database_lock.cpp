#include "database_lock.h"

#include <darkroom/error.h>

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace darkroom::cinema_detail {

namespace {

std::string readPid(int fd) {
    char buf[32] = {};
    const ssize_t n = ::pread(fd, buf, sizeof buf - 1, 0);
    std::string s = n > 0 ? std::string(buf, std::size_t(n)) : std::string();
    while (!s.empty() && (s.back() == '\n' || s.back() == ' ')) s.pop_back();
    return s.empty() ? std::string("unknown") : s;
}

void refuseUnlessPlainFile(int fd, const std::string& path) {
    struct stat st {};
    if (::fstat(fd, &st) != 0) {
        const int err = errno;
        ::close(fd);
        throw Error(fmt::format("cannot lock '{}': {}", path, std::strerror(err)));
    }
    if (!S_ISREG(st.st_mode) || st.st_nlink != 1) {
        ::close(fd);
        throw Error(fmt::format("'{}' is {}, not a lock file Darkroom made; refusing to write it (remove it if no "
                                "Darkroom process is writing the database)",
                                path, S_ISREG(st.st_mode) ? "a file with several names (a hard link)"
                                                          : "not a plain file"));
    }
}

}  // namespace

DatabaseLock::DatabaseLock(const std::string& folder) : path_(folder + "/" + kFileName) {
    // A finishing writer unlinks the lock file while holding it; if we opened
    // that file just before, our lock is on a dead inode. Retry until the
    // locked file is the one at the path.
    for (int attempt = 0; attempt < 100; ++attempt) {
        // Never through a symbolic link, never a file with other names: the
        // lock file is truncated and written, and a planted link or hard link
        // would make us overwrite its target.
        const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC, 0644);
        if (fd < 0 && errno == ELOOP)
            throw Error(fmt::format("'{}' is a symbolic link, which Darkroom never makes; refusing to follow it "
                                    "(remove it if no Darkroom process is writing the database)",
                                    path_));
        if (fd < 0)
            throw Error(fmt::format("cannot create lock file '{}': {}", path_, std::strerror(errno)));
        refuseUnlessPlainFile(fd, path_);
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
            const int err = errno;
            const std::string pid = readPid(fd);
            ::close(fd);
            if (err == EWOULDBLOCK)
                throw Error(fmt::format("database {} is being written by another process (pid {})",
                                        folder, pid));
            throw Error(fmt::format("cannot lock '{}': {}", path_, std::strerror(err)));
        }
        struct stat a {}, b {};
        if (::fstat(fd, &a) == 0 && ::stat(path_.c_str(), &b) == 0 && a.st_ino == b.st_ino &&
            a.st_dev == b.st_dev) {
            fd_ = fd;
            const std::string pid = std::to_string(::getpid()) + "\n";
            if (::ftruncate(fd_, 0) != 0 || ::pwrite(fd_, pid.data(), pid.size(), 0) < 0) {
                // The lock holds without the pid; the message will say "unknown".
            }
            return;
        }
        ::close(fd);
    }
    throw Error(fmt::format("cannot lock '{}': it keeps being replaced by another process", path_));
}

// Every path out removes the lock file (a refusal too): only a killed
// process leaves one, and the next writer takes that over.
DatabaseLock::~DatabaseLock() { releaseAndRemove(); }

void DatabaseLock::releaseAndRemove() {
    if (fd_ < 0) return;
    ::unlink(path_.c_str());
    ::close(fd_);
    fd_ = -1;
}

}  // namespace darkroom::cinema_detail
