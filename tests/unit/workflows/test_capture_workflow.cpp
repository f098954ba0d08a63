// The capture workflow called directly, without the runner: what it writes,
// what a resume renders, how it refuses, fails and stops. (Over processes it
// is tested through mpirun: mpi/tests/capture_over_ranks_test.cpp.)
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/workflows/capture.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

// Three cameras along x; the "picture" is its camera's x everywhere.
std::vector<workflows::CaptureEntry> threeEntries() {
    std::vector<workflows::CaptureEntry> out;
    for (int k = 0; k < 3; ++k) {
        workflows::CaptureEntry e;
        e.parameters.emplace("x", CinemaValue(double(k)));
        e.camera.position = {double(k), 0, 5};
        e.label = "x=" + std::to_string(k);
        out.push_back(e);
    }
    return out;
}

struct Capture {
    test::TempDir dir;
    std::string path = dir.file("db.cdb");
    std::unique_ptr<CinemaWriter> writer;
    CinemaWriterOptions options;
    std::vector<Camera> rendered;
    workflows::CaptureSettings settings;
    workflows::RenderFn render = [this](const Camera& c, const CaptureRequest&) {
        rendered.push_back(c);
        return test::makeImage(4, 3, {"Z"}, [&](int, int, int) { return float(c.position.x); });
    };
    Capture() {
        settings.openDatabase = [this]() -> CinemaWriter& {
            writer = std::make_unique<CinemaWriter>(path, std::vector<std::string>{"x"}, options);
            return *writer;
        };
    }
    workflows::CaptureSummary run() {
        SingleProcess alone;
        auto summary = workflows::captureEntries(threeEntries(), render, alone, settings);
        if (writer) writer->finish();
        writer.reset();
        return summary;
    }
};

}  // namespace

TEST(CaptureWorkflow, WritesEveryEntryWithItsAttachmentsAndReportsProgress) {
    Capture c;
    c.options.attachments.push_back({"FILE_dots", ".dots.csv"});
    c.settings.attachments = {{"FILE_dots", "x,y,z\n0,0,0\n"}};
    std::vector<std::string> labels;
    c.settings.progress = [&](double, const std::string& label) { labels.push_back(label); };
    const auto summary = c.run();
    EXPECT_EQ(summary.rendered, 3u);
    EXPECT_EQ(summary.kept, 0u);
    EXPECT_EQ(labels, (std::vector<std::string>{"x=0", "x=1", "x=2"}));
    const CinemaDatabase db = CinemaDatabase::open(c.path);
    ASSERT_EQ(db.rowCount(), 3u);
    EXPECT_EQ(test::readText(c.path + "/x=1.dots.csv"), "x,y,z\n0,0,0\n");
    EXPECT_EQ(c.rendered.size(), 3u);
}

TEST(CaptureWorkflow, AResumeRendersOnlyTheEntriesTheDatabaseLacks) {
    Capture first;
    first.run();
    fs::remove(first.path + "/x=2.exr");
    Capture again;
    again.path = first.path;
    again.options.resume = true;
    bool agreed = false;
    again.settings.entriesAgreed = [&] { agreed = true; };
    const auto summary = again.run();
    EXPECT_TRUE(agreed);
    EXPECT_EQ(summary.rendered, 1u);
    EXPECT_EQ(summary.kept, 2u);
    ASSERT_EQ(again.rendered.size(), 1u);
    EXPECT_EQ(again.rendered[0].position.x, 2.0);
    EXPECT_TRUE(fs::is_regular_file(first.path + "/x=2.exr"));
}

TEST(CaptureWorkflow, ARefusedDatabaseIsAnInputErrorAndNothingIsRendered) {
    Capture first;
    first.run();
    Capture again;
    again.path = first.path;  // create onto an existing database
    try {
        again.run();
        FAIL() << "not refused";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("already exists and is not empty"));
    }
    EXPECT_TRUE(again.rendered.empty());
}

TEST(CaptureWorkflow, AFailedRenderStopsTheCaptureWithItsMessageAndKeepsWhatWasWritten) {
    Capture c;
    c.render = [&c](const Camera& cam, const CaptureRequest&) -> BufferPtr {
        if (cam.position.x == 1.0) throw Error("the backend gave up");
        c.rendered.push_back(cam);
        return test::makeImage(4, 3, {"Z"}, [](int, int, int) { return 1.0f; });
    };
    EXPECT_THROW(
        {
            try {
                c.run();
            } catch (const InputError&) {
                FAIL() << "a render failure is not bad input";
            } catch (const Error& e) {
                EXPECT_STREQ(e.what(), "the backend gave up");
                throw;
            }
        },
        Error);
    c.writer->finish();
    EXPECT_EQ(CinemaDatabase::open(c.path).rowCount(), 1u);
}

TEST(CaptureWorkflow, ACancelStopsBeforeTheNextEntry) {
    Capture c;
    std::atomic<bool> cancel{false};
    c.settings.cancel = &cancel;
    c.settings.progress = [&](double, const std::string& label) {
        if (label == "x=1") cancel = true;
    };
    EXPECT_THROW(c.run(), Cancelled);
    EXPECT_EQ(c.rendered.size(), 1u);
}
