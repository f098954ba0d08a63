// SQL selection through SQLite on the shared databases, the simple form kept,
// and `darkroom info` descriptions of every shared database.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/limits.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

#define REQUIRE_SHARED(path) \
    if ((path).empty()) GTEST_SKIP() << "../shared/data/cinema is absent"

// The rows a predicate accepts, computed from the parsed cells.
template <class Pred>
std::vector<std::size_t> rowsWhere(const CinemaDatabase& db, Pred pred) {
    std::vector<std::size_t> out;
    for (std::size_t r = 0; r < db.rowCount(); ++r)
        if (pred(r)) out.push_back(r);
    return out;
}

}  // namespace

TEST(CinemaQuery, SqlOnSphereSelectsTheRightRowsInDatabaseOrder) {
    const auto path = test::sharedData("cinema/sphere.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    const std::size_t phi = db.column("phi"), theta = db.column("theta");
    const auto expected = rowsWhere(db, [&](std::size_t r) { return db.number(r, phi) > 0 && db.number(r, theta) == 0; });
    ASSERT_FALSE(expected.empty());
    EXPECT_LT(expected.size(), db.rowCount());
    EXPECT_EQ(db.query("phi > 0 AND theta = 0"), expected);
    EXPECT_EQ(db.query("WHERE phi > 0 AND theta = 0"), expected);
    EXPECT_EQ(db.selectWhere("phi > 0 AND theta = 0"), expected);
    const auto between = rowsWhere(db, [&](std::size_t r) { return db.number(r, phi) >= -100 && db.number(r, phi) <= 100; });
    EXPECT_EQ(db.query("phi BETWEEN -100 AND 100"), between);
    EXPECT_EQ(db.query("").size(), db.rowCount());
    EXPECT_TRUE(db.query("phi > 1000").empty());
}

TEST(CinemaQuery, NaNAndEmptyCellsAreNullAndTextColumnsCompareAsText) {
    const auto path = test::sharedData("cinema/test_values.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    const std::size_t phi = db.column("phi"), time = db.column("time");
    EXPECT_EQ(db.query("phi IS NULL"), rowsWhere(db, [&](std::size_t r) { return std::isnan(db.number(r, phi)); }));
    EXPECT_EQ(db.query("time IS NULL OR time >= 1"),
              rowsWhere(db, [&](std::size_t r) { return !(db.number(r, time) < 1); }));
    const auto paths = db.query("path LIKE '0001/%'");
    ASSERT_EQ(paths.size(), 1u);
    EXPECT_EQ(db.cell(paths[0], db.column("path")), "0001/0000");
}

TEST(CinemaQuery, QuotedColumnNamesAndErrorsCarryTheQuery) {
    test::TempDir dir;
    test::writeText(dir.file("data.csv"), "my value,FILE\n1,a.png\n2,b.png\n3,c.png\n");
    const auto db = CinemaDatabase::open(dir.path());
    EXPECT_EQ(db.query("\"my value\" >= 2"), (std::vector<std::size_t>{1, 2}));
    try {
        db.query("phi >");
        ADD_FAILURE() << "bad SQL accepted";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("query 'phi >'"));
        EXPECT_THAT(e.what(), HasSubstr("syntax error"));
    }
    try {
        db.query("nosuch = 1");
        ADD_FAILURE() << "unknown column accepted";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("no such column: nosuch"));
    }
    EXPECT_THROW(db.query("1); DROP TABLE input; SELECT (1"), Error);
}

TEST(CinemaQuery, SimpleFormIsRecognisedAndStillSnaps) {
    EXPECT_FALSE(CinemaDatabase::looksLikeSql("phi=30, theta=45"));
    EXPECT_FALSE(CinemaDatabase::looksLikeSql("name=\"a (b) AND c\""));
    EXPECT_FALSE(CinemaDatabase::looksLikeSql("name=Andrew"));
    EXPECT_TRUE(CinemaDatabase::looksLikeSql("phi > 0"));
    EXPECT_TRUE(CinemaDatabase::looksLikeSql("phi = 0 and theta = 0"));
    EXPECT_TRUE(CinemaDatabase::looksLikeSql("name = 'x'"));
    EXPECT_TRUE(CinemaDatabase::looksLikeSql("phi IN (1, 2)"));
    const auto path = test::sharedData("cinema/sphere.cdb");
    REQUIRE_SHARED(path);
    const auto db = CinemaDatabase::open(path);
    EXPECT_EQ(db.selectWhere("phi=-161"), db.select(CinemaDatabase::parseQuery("phi=-162")));
}

TEST(CinemaDescribe, EverySharedDatabaseIsDescribedWithoutError) {
    const auto root = test::sharedData("cinema");
    REQUIRE_SHARED(root);
    std::size_t count = 0;
    for (const auto& entry : std::filesystem::directory_iterator(root)) {
        if (entry.path().extension() != ".cdb") continue;
        ++count;
        SCOPED_TRACE(entry.path().string());
        const auto d = CinemaDatabase::open(entry.path().string()).describe();
        for (const auto& p : d.products) EXPECT_EQ(p.error, "") << p.column;
        const std::string text = formatDescription(d);
        EXPECT_THAT(text, HasSubstr("rows"));
        EXPECT_THAT(text, ::testing::Not(HasSubstr("could not")));
    }
    EXPECT_GE(count, 5u);
}

TEST(CinemaDescribe, NpzProductsShowMembersShapesAndTheComposableLayers) {
    const auto path = test::sharedData("cinema/ttk_extracts_001.cdb");
    REQUIRE_SHARED(path);
    const auto d = CinemaDatabase::open(path).describe();
    ASSERT_EQ(d.products.size(), 1u);
    EXPECT_EQ(d.products[0].width, 1024);
    EXPECT_EQ(d.products[0].height, 1024);
    const std::string text = formatDescription(d);
    EXPECT_THAT(text, HasSubstr("data.npy: <f4 (1024, 1024)"));
    EXPECT_THAT(text, HasSubstr("image i000 (1024 x 1024), 2 layers"));
    EXPECT_THAT(text, HasSubstr("layer l001 [object=012]"));
    EXPECT_THAT(text, HasSubstr("Z (from Depth)"));
    EXPECT_THAT(text, HasSubstr("blackbody.json"));
}

// D2 (issue 26): a row's parameters written as a query select that row and no
// other, whatever its text holds: quotes, SQL operators and keywords are data.
TEST(CinemaQuery, FormattedParametersOfAnyTextSelectTheirOwnRow) {
    test::TempDir dir;
    const std::vector<std::string> values = {"a",     "'a' OR 1", "it's", "x!=y", "f(1)", "a<b", "and",
                                             "null",  "R&D",      "say \"hi\"", "a, b=c", " lead", "Or"};
    std::string csv = "name,FILE\n";
    for (std::size_t k = 0; k < values.size(); ++k) {
        std::string quoted = "\"";
        for (char c : values[k]) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
        csv += quoted + "\",f" + std::to_string(k) + ".png\n";
    }
    test::writeText(dir.file("data.csv"), csv);
    const auto db = CinemaDatabase::open(dir.path());
    ASSERT_EQ(db.rowCount(), values.size());
    for (std::size_t r = 0; r < db.rowCount(); ++r) {
        const std::string q = db.formatParameters(r);
        EXPECT_FALSE(CinemaDatabase::looksLikeSql(q)) << q;
        EXPECT_EQ(db.selectWhere(q), std::vector<std::size_t>{r}) << q;
        EXPECT_EQ(db.find(q).row, r) << q;
    }
}

// M4 (issue 26): an expression that never ends (a recursive CTE) stops at
// --max-node-seconds, naming the option, and when the caller cancels.
TEST(CinemaQuery, ARecursiveQueryStopsAtTheTimeLimitAndOnCancel) {
    test::TempDir dir;
    test::writeText(dir.file("data.csv"), "phi,FILE\n1,a.png\n2,b.png\n");
    const auto db = CinemaDatabase::open(dir.path());
    const std::string forever =
        "phi IN (WITH RECURSIVE n(x) AS (SELECT 1 UNION ALL SELECT x + 1 FROM n) SELECT x FROM n WHERE x < 0)";
    const std::uint64_t before = limit(Limit::NodeMilliseconds);
    setLimit(Limit::NodeMilliseconds, 200);
    try {
        db.query(forever);
        ADD_FAILURE() << "a query without end returned";
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("--max-node-seconds"));
    }
    setLimit(Limit::NodeMilliseconds, before);
    int calls = 0;
    EXPECT_THROW(db.query(forever, [&] { return ++calls > 10; }), Cancelled);
    EXPECT_EQ(db.query("phi > 1"), std::vector<std::size_t>{1});
    EXPECT_THROW(db.query("length(randomblob(100000000)) > 0"), Error);
}
