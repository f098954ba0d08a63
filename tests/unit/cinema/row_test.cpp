// Row text (framework/data/include/darkroom/data/cinema/row.h): round trip,
// quoting, placeholders with and without number formats, clear errors.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/row.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using ::testing::HasSubstr;

TEST(CinemaRowText, RoundTripsValuesThatNeedQuoting) {
    const CinemaRow row{{"time", "0.5"}, {"label", "a, b = \"c\""}, {"pad", " x "}, {"empty", ""}};
    const std::string text = formatCinemaRow(row);
    EXPECT_EQ(text, "time=0.5, label=\"a, b = \"\"c\"\"\", pad=\" x \", empty=");
    EXPECT_EQ(parseCinemaRow(text), row);
}

TEST(CinemaRowText, ColumnGivenTwiceIsAnError) {
    try {
        parseCinemaRow("phi=1, phi=2");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("'phi' is given twice"));
    }
}

TEST(RowPlaceholders, FillsCellsAsWrittenAndWithNumberFormats) {
    const CinemaRow row{{"time", "0.125"}, {"phi", "-30"}, {"name", "run A"}};
    EXPECT_EQ(fillRowPlaceholders("t = {time} s, phi {phi}°", row, "test"), "t = 0.125 s, phi -30°");
    EXPECT_EQ(fillRowPlaceholders("{time:.2f}|{time:8.3e}|{phi:+d}|{phi:04d}", row, "test"),
              "0.12|1.250e-01|-30|-030");
    EXPECT_EQ(fillRowPlaceholders("{name:>7}|{ name }", row, "test"), "  run A|run A");
    EXPECT_EQ(fillRowPlaceholders("{{literal}} {{{phi}}}", row, "test"), "{literal} {-30}");
    EXPECT_EQ(fillRowPlaceholders("no placeholders\nsecond line", row, "test"), "no placeholders\nsecond line");
    EXPECT_TRUE(hasRowPlaceholders("a {b}"));
    EXPECT_FALSE(hasRowPlaceholders("a {{b}}"));
}

TEST(RowPlaceholders, ErrorsNameThePlaceholderAndTheColumns) {
    const CinemaRow row{{"time", "0.5"}, {"phi", "30"}};
    auto message = [&](const std::string& pattern) {
        try {
            fillRowPlaceholders(pattern, row, "node 'label'");
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(message("{theta}"), HasSubstr("placeholder {theta} names no column of the row (columns: time, phi)"));
    EXPECT_THAT(message("{time:d}"), HasSubstr("'0.5' is not an integer"));
    EXPECT_THAT(message("{time:.2q}"), HasSubstr("cannot format '0.5' with '.2q'"));
    EXPECT_THAT(message("open {time"), HasSubstr("is not closed"));
    EXPECT_THAT(message("close }"), HasSubstr("a single '}'"));
    EXPECT_THAT(message("{theta}"), HasSubstr("node 'label'"));
}
