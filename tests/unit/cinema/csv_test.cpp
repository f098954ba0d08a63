// The tolerant data.csv reader on the variants real databases contain, and
// its strict mode.
#include <darkroom/error.h>
#include <darkroom/data/cinema/csv.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

std::string warningsText(const CsvTable& t) {
    std::string s;
    for (const auto& w : t.warnings) s += w.str() + "\n";
    return s;
}

}  // namespace

TEST(CinemaCsv, QuotedCellsKeepCommasAndDoubledQuotes) {
    const auto t = parseCsv("a,FILE,c\n\"1.0\",\"x, y.png\",\"say \"\"hi\"\"\"\n", "q.csv");
    ASSERT_EQ(t.rows.size(), 1u);
    EXPECT_EQ(t.rows[0][0], "1.0");
    EXPECT_EQ(t.rows[0][1], "x, y.png");
    EXPECT_EQ(t.rows[0][2], "say \"hi\"");
    EXPECT_TRUE(t.warnings.empty()) << warningsText(t);
}

TEST(CinemaCsv, SpacesAfterCommasAreTrimmedInNamesAndValues) {
    const auto t = parseCsv("FILE, angle,id\n a.png , 3.6 ,\t1\n", "s.csv");
    EXPECT_EQ(t.header, (std::vector<std::string>{"FILE", "angle", "id"}));
    EXPECT_EQ(t.rows[0], (std::vector<std::string>{"a.png", "3.6", "1"}));
    // Spaces inside quotes are data, not padding.
    const auto q = parseCsv("a\n  \" x \"  \n", "s.csv");
    EXPECT_EQ(q.rows[0][0], " x ");
}

TEST(CinemaCsv, CrlfAndBlankLinesAndByteOrderMark) {
    const auto t = parseCsv("\xEF\xBB\xBFphi,FILE\r\n1,a.png\r\n\r\n2,b.png\r\n", "crlf.csv");
    EXPECT_EQ(t.header[0], "phi");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[1][1], "b.png");
    EXPECT_EQ(t.rowLines[1], 4);  // line numbers count the blank line
    EXPECT_TRUE(t.warnings.empty()) << warningsText(t);
}

TEST(CinemaCsv, ShortAndLongRowsArePaddedAndTruncatedWithOneWarningPerKind) {
    const auto t = parseCsv("a,b,c\n1,2\n1,2,3\n4\n1,2,3,4,5\n6,7,8,9\n", "uneven.csv");
    ASSERT_EQ(t.rows.size(), 5u);
    for (const auto& r : t.rows) EXPECT_EQ(r.size(), 3u);
    EXPECT_EQ(t.rows[0][2], "");
    EXPECT_EQ(t.rows[3], (std::vector<std::string>{"1", "2", "3"}));
    ASSERT_EQ(t.warnings.size(), 2u) << warningsText(t);
    const std::string w = warningsText(t);
    // Each kind names the first line where it occurs and how often it occurs.
    EXPECT_THAT(w, HasSubstr("uneven.csv:2: warning: row has fewer cells"));
    EXPECT_THAT(w, HasSubstr("uneven.csv:5: warning: row has more cells"));
    EXPECT_THAT(w, HasSubstr("2 occurrences"));
}

TEST(CinemaCsv, StrictModeTurnsIrregularitiesIntoErrorsNamingFileAndLine) {
    CsvReadOptions strict;
    strict.strict = true;
    try {
        parseCsv("a,b,c\n1,2,3\n1,2\n", "strict.csv", strict);
        FAIL() << "a short row must be an error in strict mode";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("strict.csv:3"));
        EXPECT_THAT(e.what(), HasSubstr("fewer cells"));
    }
    EXPECT_THROW(parseCsv("a,a\n1,2\n", "dup.csv", strict), Error);
    EXPECT_THROW(parseCsv("a\n\"open\n", "quote.csv", strict), Error);
    EXPECT_NO_THROW(parseCsv("a,\"b\"\n1,\"2\"\n", "fine.csv", strict));
}

TEST(CinemaCsv, UnterminatedQuoteAndTextAfterQuoteAreWarnedNotFatal) {
    const auto t = parseCsv("a,b\n\"x\"y,\"open\n2,3\n", "quotes.csv");
    ASSERT_EQ(t.rows.size(), 2u);
    EXPECT_EQ(t.rows[0][0], "xy");
    EXPECT_EQ(t.rows[0][1], "open");
    EXPECT_EQ(t.rows[1][1], "3");  // the stray quote did not swallow the next line
    const std::string w = warningsText(t);
    EXPECT_THAT(w, HasSubstr("quotes.csv:2"));
    EXPECT_THAT(w, HasSubstr("not closed"));
    EXPECT_THAT(w, HasSubstr("after the closing quote"));
}

TEST(CinemaCsv, EmptyFileIsAnErrorNamingTheFile) {
    try {
        parseCsv("\n \n", "empty.csv");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("empty.csv"));
        EXPECT_THAT(e.what(), HasSubstr("header"));
    }
    EXPECT_THROW(readCsvFile("/nonexistent/data.csv"), Error);
}

TEST(CinemaCsv, NumbersInEveryNotation) {
    double v = 0;
    EXPECT_TRUE(parseCsvNumber("1.0", v) && v == 1.0);
    EXPECT_TRUE(parseCsvNumber("-22.5", v) && v == -22.5);
    EXPECT_TRUE(parseCsvNumber("+3", v) && v == 3.0);
    EXPECT_TRUE(parseCsvNumber("1e-3", v) && v == 1e-3);
    EXPECT_TRUE(parseCsvNumber("2.5E+2", v) && v == 250.0);
    EXPECT_TRUE(parseCsvNumber(".5", v) && v == 0.5);
    EXPECT_TRUE(parseCsvNumber("007", v) && v == 7.0);
    for (const char* nan : {"NaN", "nan", "NAN", "-nan"}) {
        EXPECT_TRUE(parseCsvNumber(nan, v)) << nan;
        EXPECT_TRUE(std::isnan(v)) << nan;
    }
    EXPECT_TRUE(parseCsvNumber("-Inf", v) && std::isinf(v) && v < 0);
    EXPECT_TRUE(parseCsvNumber("1e999", v) && std::isinf(v));
    EXPECT_TRUE(parseCsvNumber("-1e999", v) && std::isinf(v) && v < 0);
    EXPECT_TRUE(parseCsvNumber("1e-999", v) && v == 0.0);
    for (const char* bad : {"", "-", "abc", "1.0x", "0x10", "1,0", " 1", "e5", "--1"})
        EXPECT_FALSE(parseCsvNumber(bad, v)) << bad;
}

TEST(CinemaCsv, NumbersFormatShortestAndReadBackExactly) {
    EXPECT_EQ(formatCsvNumber(30.0), "30");
    EXPECT_EQ(formatCsvNumber(-22.5), "-22.5");
    EXPECT_EQ(formatCsvNumber(-0.0), "0");
    EXPECT_EQ(formatCsvNumber(0.1), "0.1");
    EXPECT_EQ(formatCsvNumber(std::nan("")), "nan");
    for (double x : {0.1 + 0.2, 1e-7, 123456789.125, -3.0e300, 1.0 / 3.0}) {
        double back = 0;
        ASSERT_TRUE(parseCsvNumber(formatCsvNumber(x), back)) << formatCsvNumber(x);
        EXPECT_EQ(back, x);
    }
}

TEST(CinemaCsv, QuotingRoundTripsThroughTheReader) {
    const std::vector<std::string> cells = {"plain", "a,b", "say \"x\"", " padded ", ""};
    std::string line;
    for (const auto& c : cells) line += (line.empty() ? "" : ",") + quoteCsvCell(c);
    const auto t = parseCsv("c1,c2,c3,c4,c5\n" + line + "\n", "round.csv");
    EXPECT_EQ(t.rows.at(0), cells);
}

TEST(CinemaCsv, FileColumnNames) {
    for (const char* yes : {"FILE", "FILE2", "FILE_png", "FILE_depth"})
        EXPECT_TRUE(isCinemaFileColumn(yes)) << yes;
    for (const char* no : {"file", "FILES", "PROFILE", "path", "FILEx"})
        EXPECT_FALSE(isCinemaFileColumn(no)) << no;
}

// Random text built from the characters that matter to the parser: the
// tolerant reader must always return a rectangular table (or say the file is
// empty), the strict one a table or a darkroom::Error — never crash or hang.
TEST(CinemaCsv, RandomInputNeverCrashes) {
    const std::string alphabet = ",,,\"\"\n\n\r  \t1.e-+NnaFILE_x\xEF\xBB\xBF";
    std::uint64_t state = 0x9E3779B97F4A7C15ull;
    auto next = [&] {
        state ^= state << 13;
        state ^= state >> 7;
        state ^= state << 17;
        return state;
    };
    CsvReadOptions strict;
    strict.strict = true;
    int tables = 0;
    for (int i = 0; i < 3000; ++i) {
        std::string text(next() % 80, ' ');
        for (char& c : text) c = alphabet[next() % alphabet.size()];
        try {
            const auto t = parseCsv(text, "fuzz.csv");
            ++tables;
            EXPECT_EQ(t.rows.size(), t.rowLines.size());
            for (const auto& r : t.rows) ASSERT_EQ(r.size(), t.header.size()) << text;
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr("empty")) << text;
        }
        try {
            parseCsv(text, "fuzz.csv", strict);
        } catch (const Error& e) {
            EXPECT_THAT(e.what(), HasSubstr("fuzz.csv:")) << text;
        }
    }
    EXPECT_GT(tables, 2000);
}
