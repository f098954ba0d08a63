// An LD_PRELOAD shim for tests of data safety, without root or strace:
//   DARKROOM_SHIM_LOG=file         appends "rename <new path>" and "fsync <path>"
//                                  for every rename and fsync, in order;
//   DARKROOM_SHIM_FAIL_FSYNC=text  fsync of a file whose path contains text fails (EIO);
//   DARKROOM_SHIM_FAIL_CLOSE=text  close of such a file closes it but reports EIO,
// as a network file system or a failing disk reports a lost write late.
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <dlfcn.h>
#include <fcntl.h>
#include <string>
#include <unistd.h>

namespace {

std::string pathOf(int fd) {
    char link[64], target[4096];
    std::snprintf(link, sizeof link, "/proc/self/fd/%d", fd);
    const ssize_t n = ::readlink(link, target, sizeof target - 1);
    return n > 0 ? std::string(target, std::size_t(n)) : std::string();
}

void log(const char* what, const std::string& path) {
    const char* file = std::getenv("DARKROOM_SHIM_LOG");
    if (!file || !*file) return;
    const int saved = errno;
    const int fd = ::open(file, O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
    if (fd >= 0) {
        const std::string line = std::string(what) + " " + path + "\n";
        if (::write(fd, line.data(), line.size()) < 0) {
        }
        ::close(fd);
    }
    errno = saved;
}

bool chosen(const char* variable, const std::string& path) {
    const char* text = std::getenv(variable);
    return text && *text && path.find(text) != std::string::npos;
}

template <class F>
F next(const char* name) {
    return reinterpret_cast<F>(::dlsym(RTLD_NEXT, name));
}

}  // namespace

// The project builds with hidden visibility: the shim's calls must be seen.
#define SHIM_EXPORT __attribute__((visibility("default")))

extern "C" {

SHIM_EXPORT int rename(const char* from, const char* to) {
    static auto real = next<int (*)(const char*, const char*)>("rename");
    const int r = real(from, to);
    if (r == 0) log("rename", to);
    return r;
}

SHIM_EXPORT int fsync(int fd) {
    static auto real = next<int (*)(int)>("fsync");
    const std::string path = pathOf(fd);
    if (chosen("DARKROOM_SHIM_FAIL_FSYNC", path)) {
        errno = EIO;
        return -1;
    }
    const int r = real(fd);
    if (r == 0) log("fsync", path);
    return r;
}

SHIM_EXPORT int close(int fd) {
    static auto real = next<int (*)(int)>("close");
    const bool fail = std::getenv("DARKROOM_SHIM_FAIL_CLOSE") && chosen("DARKROOM_SHIM_FAIL_CLOSE", pathOf(fd));
    const int r = real(fd);
    if (fail && r == 0) {
        errno = EIO;
        return -1;
    }
    return r;
}
}
