// The database model on every real database in ../shared/data/cinema and on
// edge cases written here.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;
namespace fs = std::filesystem;

namespace {

std::string sharedDb(const std::string& name) { return test::sharedData("cinema/" + name); }

#define REQUIRE_SHARED(path)                                                           \
    if ((path).empty()) GTEST_SKIP() << "../shared/data/cinema is absent; real-database " \
                                        "tests need it"

std::string names(const CinemaDatabase& db, const std::vector<std::size_t>& cols) {
    std::string s;
    for (auto c : cols) s += (s.empty() ? "" : ",") + db.columns()[c].name;
    return s;
}

}  // namespace

TEST(CinemaDatabase, SphereHasThetaPhiAndNestedProducts) {
    const auto path = sharedDb("sphere.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.rowCount(), 20u);
    EXPECT_EQ(names(db, db.parameterColumns()), "theta,phi");
    EXPECT_EQ(names(db, db.fileColumns()), "FILE");
    const auto& phi = db.columns()[db.column("phi")];
    EXPECT_TRUE(phi.numeric);
    EXPECT_EQ(phi.minimum, -180);
    EXPECT_EQ(phi.maximum, 162);
    EXPECT_EQ(phi.distinct.size(), 20u);
    EXPECT_TRUE(db.warnings().empty());
    const auto m = db.find("phi=-162, theta=0");
    EXPECT_EQ(db.cell(m.row, db.column("FILE")), "image/-162/0.png");
    EXPECT_TRUE(fs::exists(db.productPath(m.row)));
    EXPECT_EQ(fs::path(db.productPath(m.row)),
              (fs::path(path) / "image/-162/0.png").lexically_normal());
}

TEST(CinemaDatabase, MultipleArtifactsHasTwoFileColumns) {
    const auto path = sharedDb("multiple_artifacts.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(names(db, db.fileColumns()), "FILE,FILE2");
    const auto row = db.find("phi=-144").row;
    EXPECT_THAT(db.productPath(row, "FILE2"), HasSubstr("image_02/-144/0.png"));
    EXPECT_THAT(db.productPath(row), HasSubstr("image/-144/0.png"));
    EXPECT_TRUE(fs::exists(db.productPath(row, "FILE2")));
}

TEST(CinemaDatabase, TtkExtractsHasFileSecondAndQuotedNumbers) {
    const auto path = sharedDb("ttk_extracts_001.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.rowCount(), 6u);
    EXPECT_EQ(db.columns()[1].name, "FILE");
    EXPECT_TRUE(db.columns()[1].isFile);
    const auto& version = db.columns()[db.column("CISVersion")];
    EXPECT_TRUE(version.numeric);  // "1.0" quoted is still a number
    EXPECT_EQ(version.minimum, 1.0);
    EXPECT_FALSE(db.columns()[db.column("CISChannel")].numeric);
    EXPECT_EQ(db.columns()[db.column("CISChannelColormap")].missing, 4u);
    const auto row = db.find("object=012, CISChannel=Elevation").row;
    EXPECT_EQ(db.cell(row, db.column("FILE")), "012_Elevation.npz");
    EXPECT_EQ(db.cell(row, db.column("CISChannelColormap")), "colormap/blackbody.json");
    // "012" keeps its spelling in the formatted parameters.
    EXPECT_THAT(db.formatParameters(row), HasSubstr("object=012"));
}

TEST(CinemaDatabase, TestValuesHasEmptyCellsNanAndNoFileColumn) {
    const auto path = sharedDb("test_values.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.rowCount(), 6u);
    EXPECT_TRUE(db.fileColumns().empty());
    const auto& time = db.columns()[db.column("time")];
    EXPECT_TRUE(time.numeric);
    EXPECT_EQ(time.missing, 1u);
    EXPECT_EQ(time.minimum, 1.0);
    EXPECT_EQ(time.maximum, 5.0);
    EXPECT_TRUE(std::isnan(db.number(0, db.column("time"))));
    EXPECT_TRUE(std::isnan(db.number(1, db.column("phi"))));
    EXPECT_EQ(db.find("time=").row, 0u);   // empty = missing
    EXPECT_EQ(db.find("phi=NaN").row, 1u);
    EXPECT_FALSE(db.columns()[db.column("path")].numeric);
    try {
        db.productPath(0);
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("no FILE column"));
    }
    EXPECT_THAT(db.productPath(2, "path"), HasSubstr("0002/0000"));  // any column by name
}

TEST(CinemaDatabase, PeriodicPictureHasLeadingSpacesInTheHeader) {
    const auto path = sharedDb("periodicPicture.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.rowCount(), 100u);
    EXPECT_EQ(names(db, db.parameterColumns()), "angle,id");
    EXPECT_EQ(db.columns()[0].name, "FILE");
    const auto m = db.find("angle=10.8");
    EXPECT_EQ(db.cell(m.row, db.column("id")), "3");
    EXPECT_TRUE(m.notes.empty());
    const auto near = db.find("angle=11");
    EXPECT_EQ(near.row, m.row);
    ASSERT_EQ(near.notes.size(), 1u);
    EXPECT_THAT(near.notes[0], HasSubstr("nearest value 10.8"));
}

// The runner iterates rows by formatting them and the CinemaReader finds them
// again: that must round-trip on every database we know.
TEST(CinemaDatabase, FormatParametersFindsTheSameValuesOnEveryRealDatabase) {
    const auto root = test::sharedData("cinema");
    REQUIRE_SHARED(root);
    int databases = 0;
    for (const auto& e : fs::directory_iterator(root)) {
        if (!fs::exists(e.path() / "data.csv")) continue;
        ++databases;
        const auto db = CinemaDatabase::open(e.path().string());
        for (std::size_t r = 0; r < db.rowCount(); ++r) {
            const auto q = db.formatParameters(r);
            const auto found = db.find(q).row;
            for (auto c : db.parameterColumns())
                EXPECT_EQ(db.cell(found, c), db.cell(r, c)) << e.path() << " " << q;
            EXPECT_FALSE(db.entryName(r).empty());
            EXPECT_EQ(db.entryName(r).find('/'), std::string::npos);
        }
    }
    EXPECT_EQ(databases, 5);
}

TEST(CinemaDatabase, NoMatchListsTheAvailableValues) {
    const auto path = sharedDb("sphere.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    try {
        db.find("phi=1000");
        FAIL() << "phi=1000 is far outside the database";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("sphere.cdb"));
        EXPECT_THAT(e.what(), HasSubstr("phi: -180, -162"));
    }
    try {
        db.find("rho=1");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("no column 'rho'"));
        EXPECT_THAT(e.what(), HasSubstr("theta, phi, FILE"));
    }
    EXPECT_THROW(db.find("phi=abc"), Error);
    EXPECT_THROW(db.find("phi"), Error);
    EXPECT_TRUE(db.select(CinemaDatabase::parseQuery("theta=5")).empty());
    EXPECT_EQ(db.select(CinemaDatabase::parseQuery("theta=0")).size(), 20u);
}

TEST(CinemaDatabase, QueriesQuoteValuesWithCommas) {
    const auto q = CinemaDatabase::parseQuery(" name = \"a, \"\"b\"\"\" , x=1,");
    ASSERT_EQ(q.size(), 2u);
    EXPECT_EQ(q[0].column, "name");
    EXPECT_EQ(q[0].value, "a, \"b\"");
    EXPECT_EQ(q[1].value, "1");
    EXPECT_THROW(CinemaDatabase::parseQuery("a=\"open"), Error);
    EXPECT_TRUE(CinemaDatabase::parseQuery("").empty());
}

TEST(CinemaDatabase, EdgeCasesWrittenHere) {
    test::TempDir dir;
    fs::create_directories(dir.file("edge.cdb"));
    // FILE_png in the middle, exponent notation, a text column with a comma,
    // CRLF, a short row and a long row.
    test::writeText(dir.file("edge.cdb/data.csv"),
                    "time , FILE_png, label ,scale\r\n"
                    "1e-3,a.png,\"x, y\",2.5E1\r\n"
                    "2e-3,b.png,z\r\n"
                    "3e-3,c.png,w,1,extra\r\n");
    const auto db = CinemaDatabase::open(dir.file("edge.cdb"));
    EXPECT_EQ(names(db, db.fileColumns()), "FILE_png");
    EXPECT_EQ(db.columns()[0].name, "time");
    EXPECT_EQ(db.columns()[0].minimum, 1e-3);
    EXPECT_EQ(db.columns()[3].maximum, 25.0);
    EXPECT_EQ(db.columns()[3].missing, 1u);
    EXPECT_EQ(db.warnings().size(), 2u);
    const auto row = db.find("label=\"x, y\"").row;
    EXPECT_EQ(db.productPath(row, "FILE_png"), dir.file("edge.cdb/a.png"));
    EXPECT_EQ(db.find(db.formatParameters(0)).row, 0u);
    // Opening data.csv itself works too.
    EXPECT_EQ(CinemaDatabase::open(dir.file("edge.cdb/data.csv")).rowCount(), 3u);
    CsvReadOptions strict;
    strict.strict = true;
    try {
        CinemaDatabase::open(dir.file("edge.cdb"), strict);
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("data.csv:3"));
    }
}

TEST(CinemaDatabase, MissingDatabaseAndFolderWithoutDataCsvAreErrors) {
    test::TempDir dir;
    EXPECT_THROW(CinemaDatabase::open(dir.file("nothing.cdb")), Error);
    try {
        CinemaDatabase::open(dir.path());
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("no data.csv"));
    }
    test::writeText(dir.file("data.csv"), "phi,FILE\n");
    const auto db = CinemaDatabase::open(dir.path());
    EXPECT_EQ(db.rowCount(), 0u);
    EXPECT_THROW(db.find(""), Error);
}

TEST(CinemaDatabase, DescribeReadsAProductOfEachFileColumn) {
    const auto path = sharedDb("multiple_artifacts.cdb");
    REQUIRE_SHARED(path);
    const auto d = CinemaDatabase::open(path).describe();
    EXPECT_EQ(d.rows, 20u);
    ASSERT_EQ(d.products.size(), 2u);
    for (const auto& p : d.products) {
        EXPECT_TRUE(p.error.empty()) << p.error;
        EXPECT_GT(p.width, 0);
        EXPECT_GT(p.height, 0);
        EXPECT_FALSE(p.channels.empty());
    }
    const std::string text = formatDescription(d);
    EXPECT_THAT(text, HasSubstr("20 rows"));
    EXPECT_THAT(text, HasSubstr("products of FILE2"));
    EXPECT_THAT(text, HasSubstr("number"));
}

TEST(CinemaDatabase, DescribeEveryRealDatabaseWithoutThrowing) {
    const auto root = test::sharedData("cinema");
    REQUIRE_SHARED(root);
    for (const auto& e : fs::directory_iterator(root)) {
        if (!fs::exists(e.path() / "data.csv")) continue;
        const auto d = CinemaDatabase::open(e.path().string()).describe();
        const std::string text = formatDescription(d);
        EXPECT_THAT(text, HasSubstr(std::to_string(d.rows) + " rows")) << e.path();
        EXPECT_EQ(d.products.size(), CinemaDatabase::open(e.path().string()).fileColumns().size());
    }
}
