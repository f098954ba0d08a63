// EXR is read either by the direct decoder (exr_direct.h), its chunks decoded
// in parallel on TBB, or by OpenEXR's C++ library with its thread pool
// (exr_file.cpp): blocks of lines are decompressed on its threads. The pixels
// must not depend on how many threads either has. The reader is compiled into
// this test (tests/CMakeLists.txt) to choose the path.
#include "test_support.h"

#include "exr_file.h"

#include <darkroom/data/image_io.h>

#include <ImfThreading.h>
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <cmath>
#include <cstring>
#include <vector>

using namespace darkroom;

TEST(ExrThreads, PixelsAreTheSameWhateverTheThreadCount) {
    // Tall enough for many zip blocks (16 lines each), so threads share them.
    auto b = test::makeImage(300, 700, {"R", "G", "B", "A", "Z", "value"}, [](int x, int y, int c) {
        return std::sin(float(x) * 0.37f + float(y) * 0.11f * float(c + 1)) * (c == 4 ? 100.0f : 1.0f);
    });
    test::TempDir dir;
    const std::string path = dir.file("threads.exr");
    writeImage(*b, path);
    const int before = Imf::globalThreadCount();
    io::readExr(path);  // sizes the pool once, as every read does first
    std::vector<std::shared_ptr<WritableBuffer>> reads;
    for (int threads : {0, 1, 4}) {  // the reading thread alone, one, and more than this machine's cores
        Imf::setGlobalThreadCount(threads);
        reads.push_back(io::readExr(path, io::ExrPixelPath::OpenExrOnly));
    }
    Imf::setGlobalThreadCount(before);
    for (int threads : {1, 4}) {  // the direct decoder on one TBB thread, and on more than the cores
        tbb::task_arena arena(threads);
        arena.execute([&] { reads.push_back(io::readExr(path)); });
    }
    for (const auto& r : reads) {
        ASSERT_EQ(r->channels().size(), 6u);
        for (const auto& ch : b->channels())
            EXPECT_EQ(std::memcmp(r->hostFloat(ch.name), b->hostFloat(ch.name), b->pixelCount() * 4), 0) << ch.name;
    }
}
