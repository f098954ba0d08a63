#include <darkroom/atomic_file.h>
#include <darkroom/error.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fcntl.h>
#include <unistd.h>

namespace darkroom {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void failWrite(const std::string& path, const std::string& what, int err) {
    throw Error("cannot write '" + path + "': " + what + std::strerror(err));
}

// A file system without sync support (some FUSE and network mounts) answers
// EINVAL or ENOTSUP: nothing more can be done there, and the data is written.
bool syncUnsupported(int err) { return err == EINVAL || err == ENOTSUP || err == EOPNOTSUPP; }

// fsync then close, both checked: on NFS and with quotas a failed write may
// surface only here.
void syncAndClose(int fd, const std::string& path, const std::string& temporary) {
    if (::fsync(fd) != 0 && !syncUnsupported(errno)) {
        const int err = errno;
        ::close(fd);
        std::remove(temporary.c_str());
        failWrite(path, "", err);
    }
    if (::close(fd) != 0 && errno != EINTR) {
        const int err = errno;
        std::remove(temporary.c_str());
        failWrite(path, "", err);
    }
}

// After a rename the new directory entry is durable only once the directory
// itself is synced: a crash could otherwise bring back the old file (or none).
void syncDirectoryOf(const std::string& path) {
    fs::path parent = fs::path(path).parent_path();
    if (parent.empty()) parent = ".";
    const int fd = ::open(parent.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (fd < 0) failWrite(path, "cannot open its folder to sync it: ", errno);
    if (::fsync(fd) != 0 && !syncUnsupported(errno)) {
        const int err = errno;
        ::close(fd);
        failWrite(path, "cannot sync its folder: ", err);
    }
    ::close(fd);
}

void renameIntoPlace(const std::string& temporary, const std::string& path) {
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const int err = errno;
        std::remove(temporary.c_str());
        failWrite(path, "", err);
    }
    syncDirectoryOf(path);
}

}  // namespace

std::string temporaryPathFor(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const fs::path p(path);
    const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return (p.parent_path() / (p.stem().string() + tag + p.extension().string())).string();
}

namespace {

// A new file under a fresh temporary name: never one that exists, never
// through a symbolic link (someone able to write the folder could plant
// either under the next predictable name).
int openNewTemporary(const std::string& path, std::string& name) {
    constexpr int kAttempts = 1000;
    for (int attempt = 0; attempt < kAttempts; ++attempt) {
        name = temporaryPathFor(path);
        const int fd = ::open(name.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
        if (fd >= 0) return fd;
        if (errno != EEXIST && errno != ELOOP) failWrite(path, "cannot create a temporary file beside it: ", errno);
    }
    failWrite(path, "cannot create a temporary file beside it (every name tried exists): ", EEXIST);
}

}  // namespace

std::string createTemporaryFile(const std::string& path) {
    std::string name;
    const int fd = openNewTemporary(path, name);
    if (::close(fd) != 0 && errno != EINTR) {
        const int err = errno;
        std::remove(name.c_str());
        failWrite(path, "", err);
    }
    return name;
}

void commitFile(const std::string& temporary, const std::string& path) {
    // O_NOFOLLOW: a temporary swapped for a link is not synced nor renamed into place.
    const int fd = ::open(temporary.c_str(), O_RDONLY | O_NOFOLLOW | O_CLOEXEC);
    if (fd < 0) {
        const int err = errno;
        std::remove(temporary.c_str());
        failWrite(path, "its temporary file is gone: ", err);
    }
    syncAndClose(fd, path, temporary);
    renameIntoPlace(temporary, path);
}

void writeFileAtomic(const std::string& path, std::string_view bytes) {
    std::string tmp;
    const int fd = openNewTemporary(path, tmp);
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n <= 0) {
            if (n < 0 && errno == EINTR) continue;
            const int err = n < 0 ? errno : EIO;
            ::close(fd);
            std::remove(tmp.c_str());
            failWrite(path, "", err);
        }
        done += std::size_t(n);
    }
    syncAndClose(fd, path, tmp);
    renameIntoPlace(tmp, path);
}

}  // namespace darkroom
