// Typed rows (sdk row.h): the text form's round trip and quoting, a value
// holding a row; and the data library's placeholders (data/cinema/row.h)
// with and without number formats, clear errors.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/row.h>
#include <darkroom/value.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

using namespace darkroom;
using ::testing::HasSubstr;

TEST(RowText, RoundTripsValuesThatNeedQuoting) {
    const Row row({{"time", "0.5"}, {"label", "a, b = \"c\""}, {"pad", " x "}, {"empty", ""}});
    const std::string text = formatRow(row);
    EXPECT_EQ(text, "time=0.5, label=\"a, b = \"\"c\"\"\", pad=\" x \", empty=");
    EXPECT_EQ(parseRow(text), row);
    // A port of type row takes and gives the same text (pipeline files, --set).
    EXPECT_EQ(parseValue(PortType::Row, text), Value(row));
    EXPECT_EQ(formatValue(PortType::Row, Value(row)), text);
    ASSERT_NE(row.find("label"), nullptr);
    EXPECT_EQ(*row.find("label"), "a, b = \"c\"");
    EXPECT_EQ(row.find("phi"), nullptr);
    EXPECT_EQ(row.columnNames(), "time, label, pad, empty");
}

TEST(RowText, ColumnGivenTwiceIsAnError) {
    try {
        parseRow("phi=1, phi=2");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("'phi' is given twice"));
    }
    EXPECT_THROW(Row({{"phi", "1"}, {"phi", "2"}}), Error);
    EXPECT_THROW(parseRow("phi=\"1"), Error);
    EXPECT_THROW(parseRow("phi"), Error);
}

TEST(RowText, AValueHoldingARowIsNotAString) {
    const Value v(Row(std::vector<RowCell>{{"phi", "30"}}));
    EXPECT_THROW((void)v.asString(), Error);
    EXPECT_EQ(v.asRow().cells().size(), 1u);
    EXPECT_NE(v, Value(std::string("phi=30")));
}

TEST(RowPlaceholders, FillsCellsAsWrittenAndWithNumberFormats) {
    const Row row({{"time", "0.125"}, {"phi", "-30"}, {"name", "run A"}});
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
    const Row row({{"time", "0.5"}, {"phi", "30"}});
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
