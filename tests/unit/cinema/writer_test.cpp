// The writer: file layout, read-back, refusal to overwrite, resume and the
// in-process side of locking. Cross-process locking and SIGKILL are in
// kill_resume_test.cpp.
#include "input_error.h"
#include "cinema_test_data.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/data/image_io.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <unistd.h>

using namespace darkroom;
using darkroom::test::errorOf;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

const std::vector<std::string> kColumns = {"phi", "theta"};

void writeGrid(const std::string& path, CinemaWriterOptions options = {}) {
    CinemaWriter w(path, kColumns, options);
    for (const auto& p : test::gridEntries())
        if (!w.hasEntry(p)) w.addEntry(p, *test::gridImage(p));
    w.finish();
}

}  // namespace

TEST(CinemaWriter, WritesSortedDataCsvAndOneExrPerEntry) {
    test::TempDir dir;
    const auto db = dir.file("grid.cdb");
    auto entries = test::gridEntries();
    std::reverse(entries.begin(), entries.end());  // order of adding must not matter
    {
        CinemaWriter w(db, kColumns);
        for (const auto& p : entries) w.addEntry(p, *test::gridImage(p));
        EXPECT_EQ(w.entryCount(), 20u);
        w.finish();
    }
    const std::string csv = test::readText(db + "/data.csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n', csv.find('\n', csv.find('\n') + 1) + 1) + 1),
              "phi,theta,FILE\n"
              "-45,-30,phi=-45_theta=-30.exr\n"
              "-45,0,phi=-45_theta=0.exr\n");
    EXPECT_THAT(csv, HasSubstr("\n-22.5,60,phi=-22.5_theta=60.exr\n"));
    EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 21);
    EXPECT_FALSE(fs::exists(db + "/.lock"));  // finish() removes the lock
    std::size_t files = 0;
    for (const auto& e : fs::directory_iterator(db)) files += e.path().extension() == ".exr";
    EXPECT_EQ(files, 20u);
}

TEST(CinemaWriter, ReaderReadsBackExactlyWhatWasWritten) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.rowCount(), 20u);
    EXPECT_TRUE(db.warnings().empty());
    EXPECT_TRUE(db.columns()[0].numeric);
    EXPECT_EQ(db.columns()[0].minimum, -45);
    for (const auto& p : test::gridEntries()) {
        const auto query = "phi=" + p.at("phi").str() + ", theta=" + p.at("theta").str();
        const auto row = db.find(query).row;
        const auto back = readImage(db.productPath(row));
        const auto written = test::gridImage(p);
        EXPECT_TRUE(identical(*back, *written)) << query;
        EXPECT_EQ(db.formatParameters(row), query);
    }
    const auto d = db.describe();
    ASSERT_EQ(d.products.size(), 1u);
    EXPECT_EQ(d.products[0].width, 32);
    ASSERT_TRUE(d.products[0].camera.has_value());
    EXPECT_EQ(d.products[0].channels.size(), 3u);
}

TEST(CinemaWriter, RefusesAnExistingDatabaseWithoutOverwriteOrResume) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    const std::string before = test::readText(path + "/data.csv");
    const std::string msg = errorOf([&] { CinemaWriter w(path, kColumns); });
    EXPECT_THAT(msg, HasSubstr(path));
    EXPECT_THAT(msg, HasSubstr("--overwrite"));
    EXPECT_THAT(msg, HasSubstr("--resume"));
    EXPECT_EQ(test::readText(path + "/data.csv"), before);  // untouched
    // An empty existing folder is fine.
    fs::create_directories(dir.file("empty.cdb"));
    EXPECT_NO_THROW(CinemaWriter(dir.file("empty.cdb"), kColumns).finish());
}

TEST(CinemaWriter, OverwriteStartsAfreshButNeverDeletesANonDatabase) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    CinemaWriterOptions o;
    o.overwrite = true;
    {
        CinemaWriter w(path, {"time"}, o);
        w.addEntry({{"time", 1}}, *test::gridImage({{"phi", 0}, {"theta", 0}}));
        w.finish();
    }
    EXPECT_EQ(test::readText(path + "/data.csv"), "time,FILE\n1,time=1.exr\n");
    EXPECT_FALSE(fs::exists(path + "/phi=0_theta=0.exr"));

    fs::create_directories(dir.file("home"));
    test::writeText(dir.file("home/thesis.tex"), "precious");
    const std::string msg = errorOf([&] { CinemaWriter w(dir.file("home"), kColumns, o); });
    EXPECT_THAT(msg, HasSubstr("Darkroom did not create it"));
    EXPECT_EQ(test::readText(dir.file("home/thesis.tex")), "precious");
}

TEST(CinemaWriter, ResumeKeepsCompleteEntriesAndRecomputesTheRest) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    const std::string full = test::readText(path + "/data.csv");
    // Damage it the ways an interrupted run or a user could: a product gone,
    // a temporary file left behind.
    fs::remove(path + "/phi=0_theta=30.exr");
    test::writeText(path + "/phi=45_theta=60.tmp-123-4.exr", "torn");
    CinemaWriterOptions o;
    o.resume = true;
    {
        CinemaWriter w(path, kColumns, o);
        EXPECT_EQ(w.resumedCount(), 19u);
        EXPECT_FALSE(w.hasEntry({{"phi", 0}, {"theta", 30}}));
        EXPECT_TRUE(w.hasEntry({{"phi", 45}, {"theta", 60}}));
        EXPECT_FALSE(fs::exists(path + "/phi=45_theta=60.tmp-123-4.exr"));
        std::size_t added = 0;
        for (const auto& p : test::gridEntries())
            if (!w.hasEntry(p)) w.addEntry(p, *test::gridImage(p)), ++added;
        EXPECT_EQ(added, 1u);
        w.finish();
    }
    EXPECT_EQ(test::readText(path + "/data.csv"), full);
    // Other columns cannot be resumed into.
    const std::string msg = errorOf([&] { CinemaWriter w(path, {"time"}, o); });
    EXPECT_THAT(msg, HasSubstr("columns are phi,theta,FILE"));
    EXPECT_THAT(msg, HasSubstr("--overwrite"));
}

TEST(CinemaWriter, SecondWriterInTheSameProcessIsLockedOut) {
    test::TempDir dir;
    const auto path = dir.file("grid.cdb");
    CinemaWriter first(path, kColumns);
    CinemaWriterOptions o;
    o.resume = true;
    const std::string msg = errorOf([&] { CinemaWriter second(path, kColumns, o); });
    EXPECT_THAT(msg, HasSubstr("database " + path + " is being written by another process (pid " +
                               std::to_string(::getpid()) + ")"));
    first.finish();
    EXPECT_NO_THROW(CinemaWriter(path, kColumns, o).finish());
}

TEST(CinemaWriter, EntryFileNamesAreSafeAndDeterministic) {
    test::TempDir dir;
    CinemaWriter w(dir.file("n.cdb"), {"phi", "label"});
    EXPECT_EQ(w.entryFileName({{"phi", -22.5}, {"label", "a/b c"}}), "phi=-22.5_label=a~b~c.exr");
    EXPECT_EQ(w.entryFileName({{"phi", 1e-7}, {"label", "x"}}), "phi=1e-07_label=x.exr");
    EXPECT_EQ(w.entryFileName({{"phi", -0.0}, {"label", "x"}}), "phi=0_label=x.exr");
    const auto img = test::gridImage({{"phi", 0}, {"theta", 0}});
    w.addEntry({{"phi", 1}, {"label", "a b"}}, *img);
    EXPECT_THAT(errorOf([&] { w.addEntry({{"phi", 1}, {"label", "a~b"}}, *img); }),
                HasSubstr("would share the file"));
    EXPECT_THAT(errorOf([&] { w.addEntry({{"phi", 1}}, *img); }), HasSubstr("'label' is missing"));
    EXPECT_THAT(errorOf([&] { w.addEntry({{"phi", 1}, {"label", "x"}, {"rho", 2}}, *img); }),
                HasSubstr("'rho' is not a column"));
    w.finish();
    EXPECT_THAT(errorOf([&] { w.addEntry({{"phi", 2}, {"label", "x"}}, *img); }),
                HasSubstr("after finish"));
    // The text value with a space is quoted in data.csv and reads back.
    const auto db = CinemaDatabase::open(dir.file("n.cdb"));
    EXPECT_EQ(db.cell(0, 1), "a b");
}

TEST(CinemaWriter, UnusableColumnNamesAreRefused) {
    test::TempDir dir;
    EXPECT_THAT(errorOf([&] { CinemaWriter w(dir.file("a.cdb"), {"FILE"}); }), HasSubstr("reserved"));
    EXPECT_THAT(errorOf([&] { CinemaWriter w(dir.file("b.cdb"), {"a,b"}); }), HasSubstr("not usable"));
    EXPECT_THAT(errorOf([&] { CinemaWriter w(dir.file("c.cdb"), {"x", "x"}); }), HasSubstr("twice"));
    test::writeText(dir.file("file.cdb"), "");
    EXPECT_THAT(errorOf([&] { CinemaWriter w(dir.file("file.cdb"), {"x"}); }),
                HasSubstr("a file of that name exists"));
}

TEST(CinemaWriter, PngProductsAndAttachmentColumnsReadBackAndResume) {
    test::TempDir dir;
    const auto path = dir.file("shaded.cdb");
    CinemaWriterOptions o;
    o.productExtension = ".png";
    o.attachments = {{"FILE_points", ".points.csv"}};
    auto colour = [](double v) {
        return test::makeImage(4, 3, {"R", "G", "B"}, [=](int, int, int c) { return float(v) * 0.1f * float(c + 1); });
    };
    {
        CinemaWriter w(path, {"time"}, o);
        w.addEntry({{"time", CinemaValue(2.0)}}, *colour(2), {{"FILE_points", "x,y,z\n2,0,0\n"}});
        w.addEntry({{"time", CinemaValue(1.0)}}, *colour(1), {{"FILE_points", "x,y,z\n1,0,0\n"}});
        EXPECT_THAT(errorOf([&] { w.addEntry({{"time", CinemaValue(3.0)}}, *colour(3)); }),
                    HasSubstr("the file for column FILE_points is missing"));
        EXPECT_THAT(errorOf([&] {
                        w.addEntry({{"time", CinemaValue(3.0)}}, *colour(3),
                                   {{"FILE_points", ""}, {"FILE_other", ""}});
                    }),
                    HasSubstr("FILE_other is not an attachment column"));
        // Interrupted here: no finish().
    }
    EXPECT_EQ(test::readText(path + "/data.csv"),
              "time,FILE,FILE_points\n"
              "1,time=1.png,time=1.points.csv\n"
              "2,time=2.png,time=2.points.csv\n");
    EXPECT_EQ(test::readText(path + "/time=2.points.csv"), "x,y,z\n2,0,0\n");
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.rowCount(), 2u);
    EXPECT_EQ(db.productPath(1, "FILE_points"), path + "/time=2.points.csv");
    const auto back = readImage(db.productPath(0));
    EXPECT_NEAR(back->hostFloat("G")[0], 0.2f, 0.003f);  // 8-bit sRGB round trip
    // A resume keeps complete entries only: remove one attachment.
    fs::remove(path + "/time=2.points.csv");
    o.resume = true;
    CinemaWriter again(path, {"time"}, o);
    EXPECT_EQ(again.resumedCount(), 1u);
    EXPECT_TRUE(again.hasEntry({{"time", CinemaValue(1.0)}}));
    EXPECT_FALSE(again.hasEntry({{"time", CinemaValue(2.0)}}));
    again.finish();
    // Columns that cannot work are refused up front.
    o.resume = false;
    o.attachments = {{"points", ".p.csv"}};
    EXPECT_THAT(errorOf([&] { CinemaWriter bad(dir.file("bad.cdb"), {"time"}, o); }),
                HasSubstr("attachment column 'points'"));
}

TEST(CinemaWriter, CheckRefusesWhatTheConstructorWouldWithoutTouchingAnything) {
    test::TempDir dir;
    CinemaWriterOptions create, overwrite, resume;
    overwrite.overwrite = true;
    resume.resume = true;
    // Nothing there: fine, and nothing is created.
    EXPECT_NO_THROW(CinemaWriter::check(dir.file("new.cdb"), create));
    EXPECT_FALSE(fs::exists(dir.file("new.cdb")));
    test::writeText(dir.file("file.cdb"), "");
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(dir.file("file.cdb"), create); }),
                HasSubstr("a file of that name exists"));

    const auto path = dir.file("grid.cdb");
    writeGrid(path);
    const std::string before = test::readText(path + "/data.csv");
    const std::string refused = errorOf([&] { CinemaWriter::check(path + "/", create); });
    EXPECT_THAT(refused, HasSubstr("database " + path + " already exists and is not empty"));
    EXPECT_EQ(refused, errorOf([&] { CinemaWriter w(path, kColumns); }));  // the constructor's words
    EXPECT_NO_THROW(CinemaWriter::check(path, overwrite));
    EXPECT_NO_THROW(CinemaWriter::check(path, resume));
    EXPECT_EQ(test::readText(path + "/data.csv"), before);
    EXPECT_TRUE(fs::exists(path + "/phi=0_theta=30.exr"));  // overwrite only checked
    EXPECT_FALSE(fs::exists(path + "/.lock"));

    // Leftovers of an interrupted write count for create, not for resume.
    fs::create_directories(dir.file("torn.cdb"));
    test::writeText(dir.file("torn.cdb/phi=0.tmp-12-3.exr"), "torn");
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(dir.file("torn.cdb"), create); }), HasSubstr("not empty"));
    EXPECT_NO_THROW(CinemaWriter::check(dir.file("torn.cdb"), resume));
    EXPECT_TRUE(fs::exists(dir.file("torn.cdb/phi=0.tmp-12-3.exr")));

    fs::create_directories(dir.file("home"));
    test::writeText(dir.file("home/thesis.tex"), "precious");
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(dir.file("home"), overwrite); }),
                HasSubstr("Darkroom did not create it"));
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(dir.file("home"), resume); }), HasSubstr("has no data.csv"));
    EXPECT_EQ(test::readText(dir.file("home/thesis.tex")), "precious");
    fs::create_directories(dir.file("bad.cdb"));
    test::writeText(dir.file("bad.cdb/data.csv"), "phi,FILE\n1,\"a\n");
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(dir.file("bad.cdb"), resume); }), HasSubstr("cannot resume"));

    CinemaWriter holder(dir.file("busy.cdb"), kColumns);
    EXPECT_THAT(errorOf([&] { CinemaWriter::check(dir.file("busy.cdb"), resume); }),
                HasSubstr("is being written by another process"));
    holder.finish();
    EXPECT_NO_THROW(CinemaWriter::check(dir.file("busy.cdb"), resume));
}

// Entries written into separate staging databases (as the ranks of an MPI run
// do) and adopted into one give the database one writer gives, byte for byte.
TEST(CinemaWriter, AdoptedEntriesMakeTheSameDatabaseAsAddedOnes) {
    test::TempDir dir;
    writeGrid(dir.file("direct.cdb"));
    const auto entries = test::gridEntries();
    std::vector<CinemaStagedEntry> staged;
    for (int part = 0; part < 3; ++part) {
        const std::string folder = dir.file("staging/rank-" + std::to_string(part));
        CinemaWriter w(folder, kColumns);
        for (std::size_t k = part; k < entries.size(); k += 3) {
            w.addEntry(entries[k], *test::gridImage(entries[k]));
            staged.push_back({entries[k], folder + "/" + w.entryFileName(entries[k]), {}});
        }
        w.finish();
    }
    {
        CinemaWriter w(dir.file("merged.cdb"), kColumns);
        w.adoptEntries(staged);
        EXPECT_EQ(w.entryCount(), 20u);
        w.finish();
    }
    std::size_t compared = 0;
    for (const auto& e : fs::directory_iterator(dir.file("direct.cdb"))) {
        const std::string name = e.path().filename().string();
        EXPECT_EQ(test::readText(e.path().string()), test::readText(dir.file("merged.cdb/" + name))) << name;
        ++compared;
    }
    EXPECT_EQ(compared, 22u);  // data.csv, the marker and 20 products
    for (const auto& s : staged) EXPECT_FALSE(fs::exists(s.product));  // moved, not copied
}

TEST(CinemaWriter, AdoptionIsCheckedBeforeAnyFileMovesAndResumes) {
    test::TempDir dir;
    CinemaWriterOptions o;
    o.productExtension = ".png";
    o.attachments = {{"FILE_points", ".points.csv"}};
    auto colour = [](double v) {
        return test::makeImage(4, 3, {"R", "G", "B"}, [=](int, int, int c) { return float(v) * 0.1f * float(c + 1); });
    };
    std::vector<CinemaStagedEntry> staged;
    {
        CinemaWriter w(dir.file("stage.cdb"), {"time"}, o);
        for (double t : {3.0, 1.0, 2.0}) {
            const CinemaParameters p{{"time", CinemaValue(t)}};
            w.addEntry(p, *colour(t), {{"FILE_points", "x\n" + std::to_string(t) + "\n"}});
            const std::string product = dir.file("stage.cdb/" + w.entryFileName(p));
            staged.push_back({p, product, {{"FILE_points", product.substr(0, product.size() - 4) + ".points.csv"}}});
        }
        w.finish();
    }
    const std::string stagedCsv = test::readText(dir.file("stage.cdb/data.csv"));
    CinemaWriter w(dir.file("final.cdb"), {"time"}, o);
    // Bad entries are refused before the first file moves.
    auto bad = staged;
    bad[2].product = dir.file("stage.cdb/nothing.png");
    EXPECT_THAT(errorOf([&] { w.adoptEntries(bad); }), HasSubstr("its product " + bad[2].product + " is missing"));
    bad = staged;
    bad[1].attachments.clear();
    EXPECT_THAT(errorOf([&] { w.adoptEntries(bad); }), HasSubstr("the file for column FILE_points is missing"));
    bad = staged;
    bad[1].parameters = {{"time", CinemaValue(1.0)}, {"phi", CinemaValue(0.0)}};
    EXPECT_THAT(errorOf([&] { w.adoptEntries(bad); }), HasSubstr("'phi' is not a column"));
    bad = staged;
    bad[0].parameters = {{"time", CinemaValue("a b")}};  // both named time=a~b.png
    bad[1].parameters = {{"time", CinemaValue("a~b")}};
    EXPECT_THAT(errorOf([&] { w.adoptEntries(bad); }), HasSubstr("would share the file"));
    EXPECT_EQ(w.entryCount(), 0u);
    for (const auto& s : staged) EXPECT_TRUE(fs::exists(s.product) && fs::exists(s.attachments.at("FILE_points")));

    // The first two, then (after an interruption) a resume adopts the third.
    w.adoptEntries({staged[0], staged[1]});
    EXPECT_EQ(test::readText(dir.file("final.cdb/data.csv")),
              "time,FILE,FILE_points\n"
              "1,time=1.png,time=1.points.csv\n"
              "3,time=3.png,time=3.points.csv\n");
    w.finish();
    o.resume = true;
    CinemaWriter again(dir.file("final.cdb"), {"time"}, o);
    EXPECT_EQ(again.resumedCount(), 2u);
    again.adoptEntries({staged[2]});
    again.finish();
    EXPECT_EQ(test::readText(dir.file("final.cdb/data.csv")), stagedCsv);
    EXPECT_EQ(test::readText(dir.file("final.cdb/time=2.points.csv")), "x\n2.000000\n");
}
