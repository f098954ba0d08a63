// A write that fails part way (a full quota, an I/O error, a network file
// system) must throw an error naming the file and the reason, and leave what
// was at the path untouched with no temporary file beside it. The failure is
// made with RLIMIT_FSIZE (file_size_limit.h): writes past the limit fail
// with EFBIG, no root or strace needed.
#include "input_error.h"
#include "file_size_limit.h"
#include "test_support.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/formats/vti.h>
#include <darkroom/data/image_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>

using namespace darkroom;
using darkroom::test::errorOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

// Noise compresses badly: every format's file is larger than the limit, and
// the EXR (6.8 kB) smaller than a stream buffer, so its bytes first reach the
// file when OpenEXR closes it, where a failure used to be swallowed.
std::shared_ptr<WritableBuffer> noise() {
    return test::makeImage(20, 20, {"R", "G", "B", "A"}, [](int x, int y, int c) {
        unsigned h = unsigned(x) * 73856093u ^ unsigned(y) * 19349663u ^ unsigned(c + 1) * 83492791u;
        h ^= h >> 13;
        h *= 0x5bd1e995u;
        return float(h & 0xffff) / 65535.0f;
    });
}

std::size_t temporaryFiles(const std::string& dir) {
    std::size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) ++n;
    return n;
}

constexpr std::size_t kLimit = 1024;

// `write` replaces the file at `path`, written once before without a limit.
void expectCleanFailure(const std::string& dir, const std::string& path, const std::function<void()>& write,
                        bool errnoTextKnown = true) {
    write();
    const std::string before = test::readText(path);
    ASSERT_GT(before.size(), kLimit) << path;
    std::string message;
    {
        test::FileSizeLimit limit(kLimit);
        message = errorOf(write);
    }
    EXPECT_THAT(message, HasSubstr(path));
    if (errnoTextKnown) {
        EXPECT_THAT(message, HasSubstr(std::strerror(EFBIG)));
    }
    EXPECT_TRUE(test::readText(path) == before) << path << " was changed by the failed write";
    EXPECT_EQ(temporaryFiles(dir), 0u) << "a temporary file was left beside " << path;
}

}  // namespace

TEST(WriteFailure, WriteFileAtomicReportsAndKeepsTheOldFile) {
    test::TempDir dir;
    const std::string big(3 * kLimit, 'x');
    expectCleanFailure(dir.path(), dir.file("data.csv"), [&] { writeFileAtomic(dir.file("data.csv"), big); });
}

TEST(WriteFailure, NativeExrAndPngReportAndKeepTheOldFile) {
    test::TempDir dir;
    const auto image = noise();
    ImageWriteOptions none;
    none.compression = "none";
    expectCleanFailure(dir.path(), dir.file("p.exr"), [&] { writeImage(*image, dir.file("p.exr"), none); });
    expectCleanFailure(dir.path(), dir.file("p.png"), [&] { writeImage(*image, dir.file("p.png")); });
}

TEST(WriteFailure, VtiReportsAndKeepsTheOldFile) {
    test::TempDir dir;
    const auto image = noise();
    expectCleanFailure(dir.path(), dir.file("p.vti"), [&] { writeVti(dir.file("p.vti"), *image); });
}

TEST(WriteFailure, OpenImageIoFormatsReportAndKeepTheOldFile) {
    test::TempDir dir;
    const auto image = noise();
    // JPEG is encoded in memory (the errno text is ours); TIFF is written by
    // libtiff into a temporary file, whose failure OpenImageIO words itself.
    expectCleanFailure(dir.path(), dir.file("p.jpg"), [&] { writeImage(*image, dir.file("p.jpg")); });
    expectCleanFailure(
        dir.path(), dir.file("p.tif"), [&] { writeImage(*image, dir.file("p.tif")); }, false);
}
