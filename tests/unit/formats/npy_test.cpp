// .npy parsing (every dtype, both orders, both byte orders, versions) and
// .npz archives through libzip, including corrupt input.
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/npy.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>

using namespace darkroom;
using ::testing::HasSubstr;

namespace {

// .npy bytes with any header dict and payload, as numpy would write them.
std::string npy(const std::string& dict, const std::string& payload, int version = 1) {
    std::string out = "\x93NUMPY";
    out += char(version);
    out += char(0);
    const std::string header = dict + "\n";
    if (version == 1) {
        out += char(header.size() & 0xff);
        out += char(header.size() >> 8);
    } else {
        for (int b = 0; b < 4; ++b) out += char((header.size() >> (8 * b)) & 0xff);
    }
    return out + header + payload;
}

template <class T>
std::string bytesOf(const std::vector<T>& v, bool bigEndian = false) {
    std::string out;
    for (T x : v) {
        char b[sizeof(T)];
        std::memcpy(b, &x, sizeof(T));
        if (bigEndian) std::reverse(b, b + sizeof(T));
        out.append(b, sizeof(T));
    }
    return out;
}

std::string dict(const std::string& descr, bool fortran, const std::string& shape) {
    return "{'descr': '" + descr + "', 'fortran_order': " + (fortran ? "True" : "False") + ", 'shape': " + shape +
           ", }";
}

}  // namespace

TEST(Npy, COrderFloat32KeepsRowMajorValues) {
    const auto a = parseNpy(npy(dict("<f4", false, "(2, 3)"), bytesOf<float>({0, 1, 2, 10, 11, 12})), "t.npy");
    EXPECT_EQ(a.shape, (std::vector<std::size_t>{2, 3}));
    EXPECT_EQ(a.values, (std::vector<float>{0, 1, 2, 10, 11, 12}));
}

TEST(Npy, FortranOrderIsTransposedToCOrder) {
    // Fortran order stores columns first: a[0][0], a[1][0], a[0][1], ...
    const auto a = parseNpy(npy(dict("<f4", true, "(2, 3)"), bytesOf<float>({0, 10, 1, 11, 2, 12})), "t.npy");
    EXPECT_TRUE(a.fortranOrder);
    EXPECT_EQ(a.values, (std::vector<float>{0, 1, 2, 10, 11, 12}));
    // Three dimensions: first index fastest.
    std::vector<float> f;
    for (int k = 0; k < 4; ++k)
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 2; ++i) f.push_back(float(100 * i + 10 * j + k));
    const auto b = parseNpy(npy(dict("<f4", true, "(2, 3, 4)"), bytesOf(f)), "t.npy");
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 3; ++j)
            for (int k = 0; k < 4; ++k) EXPECT_EQ(b.values[std::size_t((i * 3 + j) * 4 + k)], 100 * i + 10 * j + k);
}

TEST(Npy, EveryDtypeConverts) {
    EXPECT_EQ(parseNpy(npy(dict("<f8", false, "(3,)"), bytesOf<double>({0.5, -2, 1e300})), "t").values,
              (std::vector<float>{0.5f, -2.f, std::numeric_limits<float>::infinity()}));
    EXPECT_EQ(parseNpy(npy(dict("|u1", false, "(3,)"), bytesOf<std::uint8_t>({0, 128, 255})), "t").values,
              (std::vector<float>{0, 128, 255}));
    EXPECT_EQ(parseNpy(npy(dict("<u1", false, "(2,)"), bytesOf<std::uint8_t>({7, 9})), "t").values,
              (std::vector<float>{7, 9}));
    EXPECT_EQ(parseNpy(npy(dict("<i4", false, "(3,)"), bytesOf<std::int32_t>({-5, 0, 1 << 20})), "t").values,
              (std::vector<float>{-5, 0, float(1 << 20)}));
    EXPECT_EQ(parseNpy(npy(dict("<i2", false, "(2,)"), bytesOf<std::int16_t>({-300, 300})), "t").values,
              (std::vector<float>{-300, 300}));
    EXPECT_EQ(parseNpy(npy(dict("|b1", false, "(2,)"), bytesOf<std::uint8_t>({1, 0})), "t").values,
              (std::vector<float>{1, 0}));
    // Big-endian variants are byte-swapped.
    EXPECT_EQ(parseNpy(npy(dict(">f4", false, "(2,)"), bytesOf<float>({1.5f, -3}, true)), "t").values,
              (std::vector<float>{1.5f, -3}));
    EXPECT_EQ(parseNpy(npy(dict(">i4", false, "(1,)"), bytesOf<std::int32_t>({-123456}, true)), "t").values,
              (std::vector<float>{-123456}));
    EXPECT_EQ(parseNpy(npy(dict(">f8", false, "(1,)"), bytesOf<double>({0.25}, true)), "t").values,
              (std::vector<float>{0.25f}));
}

TEST(Npy, Versions2And3HaveFourByteHeaderLengths) {
    for (int v : {2, 3}) {
        const auto a = parseNpy(npy(dict("<f4", false, "(1, 2)"), bytesOf<float>({4, 5}), v), "t.npy");
        EXPECT_EQ(a.values, (std::vector<float>{4, 5})) << "version " << v;
    }
}

TEST(Npy, MalformedHeadersAreErrorsNamingTheMember) {
    const std::string where = "x.npz:data.npy";
    const auto message = [&](const std::string& bytes) {
        try {
            parseNpy(bytes, where);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_THAT(message("PK\x03\x04 not npy at all"), HasSubstr("x.npz:data.npy: not a .npy array"));
    EXPECT_THAT(message(npy(dict("<f4", false, "(2, 2)"), bytesOf<float>({1, 2}))),
                HasSubstr("x.npz:data.npy: data is truncated"));
    EXPECT_THAT(message(npy(dict("<c8", false, "(1,)"), "12345678")), HasSubstr("unsupported dtype '<c8'"));
    EXPECT_THAT(message(npy("{'descr': [('a', '<f4')], 'fortran_order': False, 'shape': (1,), }", "1234")),
                HasSubstr("structured dtype"));
    EXPECT_THAT(message(npy("{'descr': '<f4', 'shape': (1,), }", "1234")), HasSubstr("lacks"));
    EXPECT_THAT(message(npy("{'descr': '<f4', 'fortran_order': Maybe, 'shape': (1,), }", "1234")),
                HasSubstr("True or False"));
    std::string future = npy(dict("<f4", false, "(1,)"), "1234");
    future[6] = 9;
    EXPECT_THAT(message(future), HasSubstr("unsupported .npy version 9"));
    std::string longHeader = npy(dict("<f4", false, "(1,)"), "");
    longHeader[8] = char(0xff);
    EXPECT_THAT(message(longHeader), HasSubstr("header claims"));
}

TEST(Npz, WriteThenReadKeepsMembersShapesAndValues) {
    test::TempDir dir;
    for (bool compress : {false, true}) {
        const std::string path = dir.file(compress ? "c.npz" : "s.npz");
        NpyArray a{"data", "<f4", {2, 3}, false, {1, 2, 3, 4, 5, 6}};
        NpyArray b{"other", "<f4", {3}, false, {-1, std::numeric_limits<float>::infinity(), 0.5f}};
        writeNpz(path, {a, b}, compress);
        const auto back = readNpz(path);
        ASSERT_EQ(back.size(), 2u);
        EXPECT_EQ(back[0].name, "data");
        EXPECT_EQ(back[0].shape, a.shape);
        EXPECT_EQ(back[0].values, a.values);
        EXPECT_EQ(back[1].name, "other");
        EXPECT_EQ(back[1].values, b.values);
        const auto headers = readNpzHeaders(path);
        EXPECT_EQ(headers[1].descr, "<f4");
        EXPECT_TRUE(headers[1].values.empty());
    }
}

TEST(Npz, CorruptArchivesAreErrorsNamingTheFile) {
    test::TempDir dir;
    const auto message = [](const std::string& path) {
        try {
            readNpz(path);
        } catch (const Error& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    const std::string missing = dir.file("missing.npz");
    EXPECT_THAT(message(missing), HasSubstr(missing));
    const std::string garbage = dir.file("garbage.npz");
    test::writeText(garbage, "this is not a zip archive at all, just text long enough to look");
    EXPECT_THAT(message(garbage), HasSubstr(garbage));

    // A valid archive cut short: its central directory is gone.
    const std::string good = dir.file("good.npz");
    writeNpz(good, {NpyArray{"data", "<f4", {64, 64}, false, std::vector<float>(64 * 64, 1.f)}});
    std::string bytes = test::readText(good);
    const std::string cut = dir.file("cut.npz");
    test::writeText(cut, bytes.substr(0, bytes.size() / 2));
    EXPECT_THAT(message(cut), HasSubstr(cut));

    // A stored member whose .npy magic is damaged: the CRC or the header check
    // fails, and the message names the file and the member.
    const auto at = bytes.find("\x93NUMPY");
    ASSERT_NE(at, std::string::npos);
    bytes[at + 1] = 'X';
    const std::string bad = dir.file("bad.npz");
    test::writeText(bad, bytes);
    EXPECT_THAT(message(bad), HasSubstr(bad + ":data.npy"));
    try {
        readNpzHeaders(bad);
        ADD_FAILURE() << "a damaged header was accepted";
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr(bad + ":data.npy: not a .npy array"));
    }
}
