// Regressions for data.csv and products found by fuzzing (issue 18): inputs
// that made the reader hang or grow without bound, and special files, which
// must be refused at once with an InputError naming the path.
#include "input_error.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/formats/npy.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>
#include <string>

using namespace darkroom;
using darkroom::test::inputError;
using ::testing::HasSubstr;

TEST(HostileCsv, LoneCarriageReturnsEndLines) {
    // Old Mac line ends: rows, not one header holding every cell.
    const auto t = parseCsv("a,b,FILE\r1,2,x.png\r3,4,y.png\r", "cr.csv");
    EXPECT_EQ(t.header, (std::vector<std::string>{"a", "b", "FILE"}));
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[1], (std::vector<std::string>{"3", "4", "y.png"}));
    EXPECT_EQ(t.rowLines, (std::vector<int>{2, 3}));
    // Mixed with CRLF and LF, blank lines between.
    const auto m = parseCsv("a\r\n1\r\r2\n\n3", "mixed.csv");
    ASSERT_EQ(m.rows.size(), 3u);
    EXPECT_EQ(m.rows[2][0], "3");
    EXPECT_TRUE(m.warnings.empty());
}

TEST(HostileCsv, UnterminatedQuotesEndAtTheLine) {
    std::string text = "a,b\n";
    for (int i = 0; i < 20000; ++i) text += "\"open,\"\"x\n";
    text += "\"";
    const auto t = parseCsv(text, "q.csv");
    EXPECT_EQ(t.rows.size(), 20001u);
    EXPECT_EQ(t.rows[0][0], "open,\"x");
    ASSERT_EQ(t.warnings.size(), 2u);  // the unterminated quote and the short row, each counted once
    EXPECT_THAT(t.warnings[0].str() + t.warnings[1].str(), HasSubstr("20001 occurrences"));
}

TEST(HostileCsv, ShortRowsUnderAHugeHeaderAreRefusedNotPadded) {
    // 2 MB: a header of a million columns and a million one-cell rows once
    // became 10^12 padded cells.
    std::string text(1000000, ',');
    text += '\n';
    for (int i = 0; i < 500000; ++i) text += "x\n";
    const std::string msg = inputError([&] { parseCsv(text, "wide.csv"); });
    EXPECT_THAT(msg, HasSubstr("wide.csv:"));
    EXPECT_THAT(msg, HasSubstr("1000001 columns"));
    EXPECT_THAT(msg, HasSubstr("expected rows as wide as the header"));
    // Short rows under a normal header are still padded, with a warning.
    const auto t = parseCsv("a,b,c\n1\n2,3\n", "short.csv");
    EXPECT_EQ(t.rows[0], (std::vector<std::string>{"1", "", ""}));
    EXPECT_FALSE(t.warnings.empty());
}

TEST(HostileCsv, ManyDistinctStringsOpenInLinearTime) {
    // The distinct values of a text column were found by a linear search per
    // row: n^2 string comparisons for n distinct names.
    test::TempDir dir;
    std::string text = "name,FILE\n";
    const int n = 100000;
    for (int i = 0; i < n; ++i) text += "s" + std::to_string(i) + ",f.png\n";
    test::writeText(dir.file("data.csv"), text);
    const auto db = CinemaDatabase::open(dir.path());
    const auto& col = db.columns()[db.column("name")];
    ASSERT_EQ(col.distinct.size(), std::size_t(n));
    EXPECT_EQ(col.distinct[12345], "s12345");
}

TEST(HostileCsv, SpecialFilesAreRefusedWithoutBlocking) {
    test::TempDir dir;
    const std::string fifo = dir.file("data.csv");
    ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
    EXPECT_THAT(inputError([&] { readCsvFile(fifo); }), HasSubstr("'" + fifo + "': it is a FIFO"));
    EXPECT_THAT(inputError([&] { CinemaDatabase::open(dir.path()); }), HasSubstr(fifo));
    EXPECT_THAT(inputError([&] { readCsvFile("/dev/zero"); }), HasSubstr("'/dev/zero': it is a character device"));
    EXPECT_THAT(inputError([&] { readCsvFile(dir.path()); }), HasSubstr("it is a directory"));
}

TEST(HostileCsv, AFileThatIsNotACsvIsNotReadAsADatabase) {
    // `darkroom info mesh.vtp` once printed the mesh's bytes as a column name.
    test::TempDir dir;
    const std::string mesh = dir.file("deep.vtp");
    { std::ofstream(mesh) << "<VTKFile type=\"PolyData\"></VTKFile>\n"; }
    EXPECT_THAT(inputError([&] { CinemaDatabase::open(mesh); }),
                HasSubstr("'" + mesh + "' is not a Cinema database: expected a folder holding data.csv"));
    const std::string csv = dir.file("table.csv");
    { std::ofstream(csv) << "phi\n0\n"; }
    EXPECT_EQ(CinemaDatabase::open(csv).rowCount(), 1u);
}

TEST(HostileProduct, NpzOfAMillionComponentsIsReadInLinearTime) {
    // Shape (1, 1, k): k channels, each looked up by name while the image was
    // built (k^2 string comparisons).
    test::TempDir dir;
    const std::string path = dir.file("wide.npz");
    const std::size_t k = 100000;
    std::vector<float> values(k);
    for (std::size_t i = 0; i < k; ++i) values[i] = float(i);
    writeNpz(path, {NpyArray{"v", "<f4", {1, 1, k}, false, values}});
    const auto image = readCinemaProduct(path);
    ASSERT_EQ(image->channels().size(), k);
    EXPECT_EQ(image->hostFloat("v.99999")[0], 99999.f);
}

TEST(HostileProduct, SpecialFilesAreRefused) {
    test::TempDir dir;
    for (const char* name : {"p.npz", "p.vti", "p.exr", "p.png", "p.tif"}) {
        const std::string fifo = dir.file(name);
        ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
        EXPECT_THAT(inputError([&] { readCinemaProduct(fifo); }), HasSubstr(fifo + "': it is a FIFO"));
    }
}
