#include "harness.h"

#include <darkroom/limits.h>

#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace fs = std::filesystem;

namespace fuzz {

namespace {

void removeScratch() {
    std::error_code ec;
    fs::remove_all(scratchFolder(), ec);
}

}  // namespace

const std::string& scratchFolder() {
    // Never destroyed: the exit handler that removes the folder runs after
    // function-local statics constructed before its registration are gone.
    static const std::string* folder = [] {
        const fs::path dir = fs::temp_directory_path() / ("darkroom-fuzz-" + std::to_string(::getpid()));
        fs::create_directories(dir);
        std::atexit(removeScratch);
        return new std::string(dir.string());
    }();
    return *folder;
}

std::string writeInput(const std::uint8_t* data, std::size_t size, const std::string& name) {
    const std::string path = (fs::path(scratchFolder()) / name).string();
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
    out.close();
    if (!out) throw std::runtime_error("fuzz harness: cannot write " + path);
    return path;
}

}  // namespace fuzz

// Limits well under libFuzzer's default -rss_limit_mb (2048): a reader that
// honours them never comes near it, so an allocation libFuzzer reports as
// "malloc exceeds limit" is one a limit should have refused.
extern "C" int LLVMFuzzerInitialize(int*, char***) {
    using darkroom::Limit;
    darkroom::setLimit(Limit::ImagePixels, 4u << 20);   // 4 Mpixel
    darkroom::setLimit(Limit::InputBytes, 16u << 20);   // 16 MiB
    darkroom::setLimit(Limit::DecodedBytes, 64u << 20); // 64 MiB
    return 0;
}
