// The SDK's guarded input: special files and oversized inputs are refused
// with an InputError naming the path, before anything blocks or allocates.
#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <functional>
#include <fstream>
#include <sys/stat.h>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace darkroom;

namespace {

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::temp_directory_path() / ("darkroom-input-file-" + std::to_string(::getpid()));
    fs::create_directories(dir);
    return dir / name;
}

std::string messageOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no InputError)";
}

// Restores a limit when a test ends, so tests do not leak settings.
struct LimitGuard {
    Limit which;
    std::uint64_t saved;
    explicit LimitGuard(Limit w) : which(w), saved(limit(w)) {}
    ~LimitGuard() { setLimit(which, saved); }
};

}  // namespace

TEST(InputFile, ReadsARegularFileWhole) {
    const fs::path p = scratch("a.txt");
    std::ofstream(p) << "hello";
    EXPECT_EQ(readInputFile(p.string(), "pipeline"), "hello");
    EXPECT_EQ(requireRegularFile(p.string(), "pipeline"), 5u);
}

TEST(InputFile, AFifoIsRefusedWithoutBlocking) {
    const fs::path p = scratch("fifo");
    fs::remove(p);
    ASSERT_EQ(::mkfifo(p.c_str(), 0600), 0);
    const std::string m = messageOf([&] { readInputFile(p.string(), "mesh"); });
    EXPECT_NE(m.find("a FIFO"), std::string::npos) << m;
    EXPECT_NE(m.find(p.string()), std::string::npos) << m;
    EXPECT_NE(messageOf([&] { requireRegularFile(p.string(), "mesh"); }).find("a FIFO"), std::string::npos);
}

TEST(InputFile, DevZeroAndDirectoriesAreRefused) {
    EXPECT_NE(messageOf([] { readInputFile("/dev/zero", "colour map"); }).find("a character device"),
              std::string::npos);
    EXPECT_NE(messageOf([] { readInputFile(fs::temp_directory_path().string(), "scene"); }).find("a directory"),
              std::string::npos);
}

TEST(InputFile, AMissingFileNamesThePathAndWhat) {
    const std::string m = messageOf([] { readInputFile("/nonexistent/x.yaml", "pipeline"); });
    EXPECT_NE(m.find("cannot read pipeline '/nonexistent/x.yaml'"), std::string::npos) << m;
}

TEST(InputFile, AFileOverTheInputLimitIsRefusedNamingTheOption) {
    LimitGuard guard(Limit::InputBytes);
    const fs::path p = scratch("big.txt");
    std::ofstream(p) << std::string(100, 'x');
    setLimit(Limit::InputBytes, 99);
    const std::string m = messageOf([&] { readInputFile(p.string(), "CSV"); });
    EXPECT_NE(m.find("--max-input-bytes"), std::string::npos) << m;
    setLimit(Limit::InputBytes, 100);
    EXPECT_EQ(readInputFile(p.string(), "CSV").size(), 100u);
}

TEST(Limits, ImagePixelsAreCheckedWithoutOverflow) {
    LimitGuard guard(Limit::ImagePixels);
    EXPECT_NO_THROW(checkImagePixels(16384, 16384, "a.png"));  // the default allows 16384²
    const std::string m = messageOf([] { checkImagePixels(30000, 30000, "a.png"); });
    EXPECT_NE(m.find("a.png: 30000 x 30000 pixels exceed"), std::string::npos) << m;
    EXPECT_NE(m.find("--max-image-pixels"), std::string::npos) << m;
    // A product that would wrap around 2^64 is still refused.
    EXPECT_THROW(checkImagePixels(std::uint64_t(1) << 40, std::uint64_t(1) << 40, "x"), InputError);
    setLimit(Limit::ImagePixels, 100);
    EXPECT_NO_THROW(checkImagePixels(10, 10, "x"));
    EXPECT_THROW(checkImagePixels(10, 11, "x"), InputError);
}

TEST(Limits, ZeroMeansNoLimitForBytes) {
    LimitGuard guard(Limit::NodeBytes);
    setLimit(Limit::NodeBytes, 0);
    EXPECT_NO_THROW(checkBytes(Limit::NodeBytes, ~std::uint64_t(0), "node 'x'", "planes"));
    setLimit(Limit::NodeBytes, 10);
    EXPECT_THROW(checkBytes(Limit::NodeBytes, 11, "node 'x'", "planes"), InputError);
}
