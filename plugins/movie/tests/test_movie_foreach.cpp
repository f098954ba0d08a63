// The publishing path end to end through the runner: `darkroom run --foreach`
// shades every entry of a database (ColorMapping, Annotation from the row) into
// a new database with CinemaWriter, then — once, after the last entry — Movie
// encodes it; `darkroom info` reads the result, the MP4 decodes to the right
// frames; a rerun resumes or is refused.
#include "../../../tests/integration/runner/runner_process.h"
#include "decoded_movie.h"
#include "test_support.h"

#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/data/image_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

void sourceDatabase(const std::string& path) {
    CinemaWriter w(path, {"time", "phi"});
    for (double t : {2.0, 0.0, 1.0})
        for (double phi : {0.0, 90.0}) {
            auto img = test::makeImage(48, 32, {"Z", "value"}, [=](int, int, int c) { return c == 0 ? 3.0f : float(t); });
            w.addEntry({{"time", CinemaValue(t)}, {"phi", CinemaValue(phi)}}, *img);
        }
    w.finish();
}

const char* kPipeline = R"(darkroom: 1
nodes:
  read:
    type: CinemaReader
    parameters: {database: source.cdb}
  colour:
    type: ColorMapping
    parameters: {channel: value, colormap: grayscale, range: manual, minimum: 0, maximum: 3}
  label:
    type: Annotation
    parameters: {text: "t = {time:.1f}", fontSize: 0.2, color: [1, 0, 0, 1]}
  frames:
    type: CinemaWriter
    parameters: {database: frames.cdb}
  movie:
    type: Movie
    parameters: {database: frames.cdb, where: "phi=0", orderBy: time, path: talk.mp4, frameRate: 10}
edges:
  - read.image -> colour.image
  - colour.image -> label.image
  - read.row -> label.row
  - label.image -> frames.image
  - read.row -> frames.row
)";

}  // namespace

TEST(PublishingRun, ForeachWritesADatabaseAndAMovieOfIt) {
    test::TempDir dir;
    sourceDatabase(dir.file("source.cdb"));
    test::writeText(dir.file("shade.yaml"), kPipeline);
    const std::string out = dir.file("out");
    auto r = test::runDarkroom({"-q", "run", dir.file("shade.yaml"), "--foreach", "read", "-o", out});
    ASSERT_EQ(r.exitCode, 0) << r.err;

    // One database, not one per entry; its rows are the source's.
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(out)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    EXPECT_EQ(names, (std::vector<std::string>{"frames.cdb", "talk.mp4"}));
    const auto info = test::runDarkroom({"info", out + "/frames.cdb"});
    EXPECT_EQ(info.exitCode, 0) << info.err;
    EXPECT_THAT(info.out, HasSubstr("6 rows"));
    EXPECT_THAT(info.out, HasSubstr("size     48 x 32"));
    const auto db = CinemaDatabase::open(out + "/frames.cdb");
    const auto src = CinemaDatabase::open(dir.file("source.cdb"));
    for (std::size_t row = 0; row < src.rowCount(); ++row) EXPECT_TRUE(db.find(src.formatParameters(row)).notes.empty());
    // The annotation is in the pictures (red text on grey).
    const auto picture = readImage(db.productPath(db.find("time=1, phi=90").row));
    float reddest = 0;
    for (std::size_t i = 0; i < picture->pixelCount(); ++i)
        reddest = std::max(reddest, picture->hostFloat("R")[i] - picture->hostFloat("G")[i]);
    EXPECT_GT(reddest, 0.5f);

    // The movie: the three phi=0 entries in time order, 10 fps; the bottom-right
    // pixel (no text there) is the grey of time / 3.
    const auto m = test::decodeMovie(out + "/talk.mp4", 46, 30);
    EXPECT_EQ(m.frames(), 3);
    EXPECT_EQ(m.width, 48);
    EXPECT_EQ(m.height, 32);
    EXPECT_NEAR(m.frameRate, 10.0, 1e-9);
    EXPECT_LT(m.lumaAt[0], m.lumaAt[1]);
    EXPECT_LT(m.lumaAt[1], m.lumaAt[2]);
    EXPECT_NEAR(m.lumaAt[0], 16, 3);
    // The grayscale map is a straight line in sRGB-encoded values: t = 2/3 is code 2/3.
    EXPECT_NEAR(m.lumaAt[2], 16 + 219 * 2.0 / 3.0, 3);

    // Again: create refuses the existing database, resume completes it.
    r = test::runDarkroom({"-q", "run", dir.file("shade.yaml"), "--foreach", "read", "-o", out});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.err, HasSubstr("already exists and is not empty"));
    fs::remove(out + "/frames.cdb/time=2_phi=90.png");
    r = test::runDarkroom({"-q", "run", dir.file("shade.yaml"), "--foreach", "read", "-o", out, "--set",
                           "frames.mode=resume"});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(fs::exists(out + "/frames.cdb/time=2_phi=90.png"));
    EXPECT_EQ(CinemaDatabase::open(out + "/frames.cdb").rowCount(), 6u);
}

// The Movie reads the database through CinemaWriter's `written` output: the
// name is given once, the movie is made once, after the last entry, from the
// whole database; and the same movie as when both nodes name the database.
TEST(PublishingRun, AMovieConnectedToTheWriterRunsAfterTheLastEntry) {
    test::TempDir dir;
    sourceDatabase(dir.file("source.cdb"));
    std::string connected = kPipeline;
    const std::string named = "database: frames.cdb, where";
    connected.replace(connected.find(named), named.size(), "where");
    connected += "  - frames.written -> movie.database\n";
    test::writeText(dir.file("connected.yaml"), connected);
    test::writeText(dir.file("named.yaml"), kPipeline);
    for (const char* pipeline : {"connected", "named"}) {
        const auto r = test::runDarkroom({"-q", "run", dir.file(std::string(pipeline) + ".yaml"), "--foreach", "read",
                                          "-o", dir.file(pipeline), "--profile"});
        ASSERT_EQ(r.exitCode, 0) << r.err;
        // The movie is made once, after the 6 entries, not per entry: one
        // profile line says it ran.
        std::size_t made = 0;
        std::istringstream lines(r.err);
        for (std::string line; std::getline(lines, line);)
            made += line.rfind("  movie ", 0) == 0 && line.find(" Movie ") != std::string::npos &&
                    line.find(" ran ") != std::string::npos;
        EXPECT_EQ(made, 1u) << r.err;
    }
    const auto m = test::decodeMovie(dir.file("connected/talk.mp4"), 46, 30);
    EXPECT_EQ(m.frames(), 3);
    EXPECT_LT(m.lumaAt[0], m.lumaAt[2]);
    EXPECT_EQ(test::readText(dir.file("connected/talk.mp4")), test::readText(dir.file("named/talk.mp4")));

    // Anything but a sink after the last entry reading what is written per
    // entry is refused before the first entry.
    std::string chained = connected;
    chained.replace(chained.find("edges:\n"), 7,
                    "  caption:\n    type: Annotation\nedges:\n  - read.image -> caption.image\n"
                    "  - frames.written -> caption.text\n");
    test::writeText(dir.file("chained.yaml"), chained);
    const auto refused = test::runDarkroom({"-q", "run", dir.file("chained.yaml"), "--foreach", "read", "-o",
                                            dir.file("chained")});
    EXPECT_EQ(refused.exitCode, 2) << refused.err;
    EXPECT_THAT(refused.err, HasSubstr("node 'caption' reads frames.written, which is written entry by entry"));
    EXPECT_FALSE(fs::exists(dir.file("chained/frames.cdb")));
}
