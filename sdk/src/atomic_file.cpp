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

std::string temporaryPathFor(const std::string& path) {
    static std::atomic<unsigned> counter{0};
    const fs::path p(path);
    const std::string tag = ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
    return (p.parent_path() / (p.stem().string() + tag + p.extension().string())).string();
}

void commitFile(const std::string& temporary, const std::string& path) {
    const int fd = ::open(temporary.c_str(), O_RDONLY);
    if (fd >= 0) {
        ::fsync(fd);
        ::close(fd);
    }
    if (std::rename(temporary.c_str(), path.c_str()) != 0) {
        const std::string why = std::strerror(errno);
        std::remove(temporary.c_str());
        throw Error("cannot write '" + path + "': " + why);
    }
}

void writeFileAtomic(const std::string& path, std::string_view bytes) {
    const std::string tmp = temporaryPathFor(path);
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (fd < 0) throw Error("cannot write '" + path + "': " + std::strerror(errno));
    std::size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0) {
            if (errno == EINTR) continue;
            const std::string why = std::strerror(errno);
            ::close(fd);
            std::remove(tmp.c_str());
            throw Error("cannot write '" + path + "': " + why);
        }
        done += std::size_t(n);
    }
    ::close(fd);
    commitFile(tmp, path);
}

}  // namespace darkroom
