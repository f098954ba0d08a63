#pragma once
// Helpers shared by the test executables: the build's plugins, temporary
// folders and small synthetic images made in code (no binary fixtures).
#include <darkroom/buffer.h>
#include <darkroom/core/registry.h>

#include <functional>
#include <string>

namespace darkroom::test {

// A registry with every plugin the build produced; fails the test on load errors.
Registry& pluginRegistry();

// Path of a file under ../shared/data, or "" when that folder is absent.
std::string sharedData(const std::string& relative);

// A fresh, empty directory removed when the object dies.
class TempDir {
public:
    TempDir();
    ~TempDir();
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;
    const std::string& path() const { return path_; }
    std::string file(const std::string& name) const { return path_ + "/" + name; }

private:
    std::string path_;
};

// A float image with one channel per name, each filled by fn(x, y, channelIndex).
std::shared_ptr<WritableBuffer> makeImage(int w, int h, const std::vector<std::string>& channels,
                                          const std::function<float(int, int, int)>& fn);

// Reads a whole text file (empty string if missing).
std::string readText(const std::string& path);
// "" when two folders hold the same files, with the same bytes, down every
// subfolder; otherwise a description of the differences.
std::string compareFolders(const std::string& a, const std::string& b);
void writeText(const std::string& path, const std::string& text);

}  // namespace darkroom::test
