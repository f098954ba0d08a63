// What --overwrite and --resume promise (docs/capture.md): overwrite removes
// only what Darkroom wrote and refuses a folder it did not create; resume
// refuses a database made from something else, naming what changed; a
// refusal leaves no lock; a product whose write fails is never listed.
#include "input_error.h"
#include "cinema_test_data.h"
#include "file_size_limit.h"
#include "test_support.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/cinema/writer.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <functional>

using namespace darkroom;
using darkroom::test::errorOf;
using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kColumns = {"phi", "theta"};

std::vector<CinemaOriginItem> sceneOrigin(const std::string& resolution, const std::string& content) {
    return {{"the scene file", "resolution", resolution, false},
            {"the scene file", "content", content, true},
            {"the capture options", "compression", "zip", false}};
}

void writeGrid(const std::string& path, CinemaWriterOptions options = {}) {
    CinemaWriter w(path, kColumns, options);
    for (const auto& p : test::gridEntries())
        if (!w.hasEntry(p)) w.addEntry(p, *test::gridImage(p));
    w.finish();
}

std::map<std::string, std::string> folderBytes(const std::string& dir) {
    std::map<std::string, std::string> out;
    for (const auto& f : fs::recursive_directory_iterator(dir))
        if (f.is_regular_file()) out[fs::relative(f.path(), dir).string()] = test::readText(f.path().string());
    return out;
}

}  // namespace

TEST(CinemaWriterSafety, OverwriteRemovesOnlyWhatDarkroomWrote) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    EXPECT_TRUE(fs::exists(path + "/.darkroom-database"));
    // Someone else's files beside the database, and a product of an entry
    // that an interrupted capture wrote but never listed, stay.
    test::writeText(path + "/notes.txt", "mine");
    fs::create_directories(path + "/analysis");
    test::writeText(path + "/analysis/plot.py", "mine too");
    test::writeText(path + "/phi=1_theta=2.tmp-99-1.exr", "torn");
    CinemaWriterOptions o;
    o.overwrite = true;
    {
        CinemaWriter w(path, {"time"}, o);
        w.addEntry({{"time", 1}}, *test::gridImage({{"phi", 0}, {"theta", 0}}));
        w.finish();
    }
    EXPECT_EQ(test::readText(path + "/data.csv"), "time,FILE\n1,time=1.exr\n");
    EXPECT_EQ(test::readText(path + "/notes.txt"), "mine");
    EXPECT_EQ(test::readText(path + "/analysis/plot.py"), "mine too");
    EXPECT_FALSE(fs::exists(path + "/phi=0_theta=0.exr"));
    EXPECT_FALSE(fs::exists(path + "/phi=1_theta=2.tmp-99-1.exr"));
    std::size_t exr = 0;
    for (const auto& e : fs::directory_iterator(path)) exr += e.path().extension() == ".exr";
    EXPECT_EQ(exr, 1u);
}

TEST(CinemaWriterSafety, OverwriteRefusesAFolderDarkroomDidNotCreateAndLeavesNoLock) {
    test::TempDir dir;
    // A Cinema database some other tool wrote, with a file of its own.
    const auto path = dir.file("paraview.cdb");
    fs::create_directories(path);
    test::writeText(path + "/data.csv", "time,FILE\n0,a.png\n");
    test::writeText(path + "/a.png", "picture");
    test::writeText(path + "/README", "keep me");
    const auto before = folderBytes(path);
    CinemaWriterOptions o;
    o.overwrite = true;
    const std::string first = errorOf([&] { CinemaWriter w(path, kColumns, o); });
    EXPECT_THAT(first, HasSubstr("refusing to overwrite " + path));
    EXPECT_THAT(first, HasSubstr("Darkroom did not create it"));
    EXPECT_THAT(first, HasSubstr("nothing was removed"));
    EXPECT_FALSE(fs::exists(path + "/.lock"));
    EXPECT_EQ(folderBytes(path), before);
    // Again: refused for the same reason, not for a lock left behind.
    EXPECT_EQ(errorOf([&] { CinemaWriter w(path, kColumns, o); }), first);
    EXPECT_EQ(errorOf([&] { CinemaWriter::check(path, o); }), first);
    EXPECT_FALSE(fs::exists(path + "/.lock"));
    // Resume refuses it too.
    CinemaWriterOptions r;
    r.resume = true;
    EXPECT_THAT(errorOf([&] { CinemaWriter w(path, kColumns, r); }), HasSubstr("Darkroom did not create it"));
    EXPECT_FALSE(fs::exists(path + "/.lock"));
    EXPECT_EQ(folderBytes(path), before);
}

TEST(CinemaWriterSafety, EveryRefusalReleasesTheLock) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    const std::string create = errorOf([&] { CinemaWriter w(path, kColumns); });
    EXPECT_THAT(create, HasSubstr("already exists"));
    EXPECT_FALSE(fs::exists(path + "/.lock"));
    EXPECT_EQ(errorOf([&] { CinemaWriter w(path, kColumns); }), create);
}

TEST(CinemaWriterSafety, ResumeRefusesADatabaseMadeFromSomethingElse) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    CinemaWriterOptions o;
    o.origin = sceneOrigin("64x64", "1f2e3d");
    writeGrid(path, o);
    const auto before = folderBytes(path);

    CinemaWriterOptions r = o;
    r.resume = true;
    r.origin = sceneOrigin("32x32", "4c5b6a");
    const std::string msg = errorOf([&] { CinemaWriter w(path, kColumns, r); });
    EXPECT_THAT(msg, HasSubstr("cannot resume " + path +
                               ": the scene file changed since the capture began (resolution 64x64 \u2192 32x32)"));
    EXPECT_THAT(msg, HasSubstr("--overwrite"));
    EXPECT_FALSE(fs::exists(path + "/.lock"));
    EXPECT_EQ(folderBytes(path), before);
    EXPECT_EQ(errorOf([&] { CinemaWriter::check(path, r); }), msg);

    // Only the content differs: the hash is named.
    r.origin = sceneOrigin("64x64", "4c5b6a");
    EXPECT_THAT(errorOf([&] { CinemaWriter w(path, kColumns, r); }),
                HasSubstr("the scene file changed since the capture began (content 1f2e3d \u2192 4c5b6a)"));
    // An option, and the product format.
    r.origin = o.origin;
    r.origin[2].value = "piz";
    EXPECT_THAT(errorOf([&] { CinemaWriter w(path, kColumns, r); }),
                HasSubstr("the capture options changed since the capture began (compression zip \u2192 piz)"));
    r.origin = o.origin;
    r.productExtension = ".png";
    EXPECT_THAT(errorOf([&] { CinemaWriter w(path, kColumns, r); }), HasSubstr("products .exr \u2192 .png"));

    // The same origin resumes, and the folder ends as it was.
    r = o;
    r.resume = true;
    {
        CinemaWriter w(path, kColumns, r);
        EXPECT_EQ(w.resumedCount(), 20u);
        w.finish();
    }
    EXPECT_EQ(folderBytes(path), before);
}

TEST(CinemaWriterSafety, AProductWhoseWriteFailsIsNeverListed) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    const auto entries = test::gridEntries();
    CinemaWriter w(path, kColumns);
    w.addEntry(entries[0], *test::gridImage(entries[0]));
    const std::string csv = test::readText(path + "/data.csv");
    std::string message;
    {
        // data.csv and the marker fit; a product does not.
        test::FileSizeLimit limit(csv.size() + 200);
        message = errorOf([&] { w.addEntry(entries[1], *test::gridImage(entries[1])); });
    }
    EXPECT_THAT(message, HasSubstr(path + "/" + w.entryFileName(entries[1])));
    EXPECT_THAT(message, HasSubstr(std::strerror(EFBIG)));
    EXPECT_EQ(test::readText(path + "/data.csv"), csv);
    EXPECT_FALSE(w.hasEntry(entries[1]));
    EXPECT_FALSE(fs::exists(path + "/" + w.entryFileName(entries[1])));
    for (const auto& e : fs::directory_iterator(path))
        EXPECT_THAT(e.path().filename().string(), Not(HasSubstr(".tmp-")));
    w.finish();
    EXPECT_EQ(test::readText(path + "/data.csv"), csv);
}

// S1 (issue 26): the lock file is written (truncated, then our pid), so a
// planted symbolic or hard link at DB/.lock must never be opened: its target
// kept byte for byte, every mode refused with a message naming the link.
TEST(CinemaWriterSafety, ALockThatIsALinkIsRefusedAndItsTargetKept) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    const auto victim = dir.file("victim.txt");
    test::writeText(victim, "precious\n");
    fs::create_symlink(victim, path + "/.lock");
    CinemaWriterOptions resume;
    resume.resume = true;
    EXPECT_THAT(errorOf([&] { CinemaWriter w(path, kColumns, resume); }), HasSubstr("is a symbolic link"));
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(path, resume); }), HasSubstr("is a symbolic link"));
    // A create is refused for the database too, and still must not touch the target.
    (void)errorOf([&] { CinemaWriter w(path, kColumns); });
    EXPECT_EQ(test::readText(victim), "precious\n");
    EXPECT_TRUE(fs::is_symlink(path + "/.lock"));

    fs::remove(path + "/.lock");
    fs::create_hard_link(victim, path + "/.lock");
    EXPECT_THAT(errorOf([&] { CinemaWriter w(path, kColumns, resume); }), HasSubstr("hard link"));
    EXPECT_EQ(test::readText(victim), "precious\n");
}

// S1: temporary files are created exclusively, never through a link planted
// under the next predictable name; the write still succeeds under another name.
TEST(CinemaWriterSafety, AtomicWritesNeverFollowAPlantedTemporaryName) {
    test::TempDir dir;
    const auto victim = dir.file("victim.txt");
    test::writeText(victim, "precious\n");
    const auto target = dir.file("out.csv");
    // The next names temporaryPathFor will hand out in this process.
    const std::string probe = temporaryPathFor(target);
    const std::string prefix = probe.substr(0, probe.rfind('-') + 1);
    const unsigned next = unsigned(std::stoul(probe.substr(prefix.size()))) + 1;
    for (unsigned k = next; k < next + 20; ++k) fs::create_symlink(victim, prefix + std::to_string(k) + ".csv");
    writeFileAtomic(target, "a,b\n1,2\n");
    EXPECT_EQ(test::readText(target), "a,b\n1,2\n");
    EXPECT_EQ(test::readText(victim), "precious\n");
    const std::string reserved = createTemporaryFile(target);
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(reserved)));
    EXPECT_EQ(fs::file_size(reserved), 0u);
    EXPECT_EQ(test::readText(victim), "precious\n");
}
