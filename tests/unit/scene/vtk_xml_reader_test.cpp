#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/scene/mesh_readers.h>

using namespace darkroom;
using darkroom::test::base64;
using darkroom::test::expectError;
using darkroom::test::put;

namespace {

enum class Format { Ascii, Binary, Appended, AppendedBase64 };

// Writes VTK XML files the way VTK does: a header word (or zlib block table)
// before each array's bytes; base64 header and data as separate streams.
class XmlWriter {
public:
    XmlWriter(Format f, bool header64, bool zlib, bool bigEndian = false)
        : format_(f), header64_(header64), zlib_(zlib), big_(bigEndian) {}

    std::string array(const std::string& name, const std::string& type, int nc, const std::vector<double>& v) {
        std::string attrs = "type=\"" + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" + std::to_string(nc) + "\"";
        if (format_ == Format::Ascii) {
            std::string s;
            for (double x : v) s += std::to_string(x) + (s.size() % 7 == 0 ? "\n" : " ");
            return "<DataArray " + attrs + " format=\"ascii\">\n" + s + "\n</DataArray>\n";
        }
        std::string raw;
        for (double x : v) {
            if (type == "Float32") put(raw, float(x), big_);
            else if (type == "Float64") put(raw, x, big_);
            else if (type == "Int32") put(raw, std::int32_t(x), big_);
            else if (type == "Int64") put(raw, std::int64_t(x), big_);
            else if (type == "UInt8") put(raw, std::uint8_t(x), big_);
        }
        std::string header, data;
        if (!zlib_) {
            word(header, raw.size());
            data = raw;
        } else {
            // Small blocks so the table has several entries and a short last block.
            const std::size_t bs = 16, nb = (raw.size() + bs - 1) / bs;
            std::vector<std::string> blocks;
            for (std::size_t i = 0; i < nb; ++i) blocks.push_back(test::zlibCompress(raw.substr(i * bs, bs)));
            word(header, nb);
            word(header, bs);
            word(header, raw.size() % bs);
            for (const auto& b : blocks) word(header, b.size());
            for (const auto& b : blocks) data += b;
        }
        if (format_ == Format::Binary)
            return "<DataArray " + attrs + " format=\"binary\">\n  " + base64(header) + base64(data) + "\n</DataArray>\n";
        const std::size_t offset = appended_.size();
        appended_ += format_ == Format::Appended ? header + data : base64(header) + base64(data);
        return "<DataArray " + attrs + " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
    }

    std::string file(const std::string& type, const std::string& body) const {
        std::string s = "<?xml version=\"1.0\"?>\n<VTKFile type=\"" + type + "\" version=\"1.0\" byte_order=\"" +
                        (big_ ? "BigEndian" : "LittleEndian") + "\" header_type=\"" + (header64_ ? "UInt64" : "UInt32") + "\"" +
                        (zlib_ ? " compressor=\"vtkZLibDataCompressor\"" : "") + ">\n<" + type + ">\n" + body + "</" + type + ">\n";
        if (format_ == Format::Appended || format_ == Format::AppendedBase64)
            s += std::string("<AppendedData encoding=\"") + (format_ == Format::Appended ? "raw" : "base64") + "\">\n   _" +
                 appended_ + "\n</AppendedData>\n";
        return s + "</VTKFile>\n";
    }

private:
    void word(std::string& s, std::size_t v) const {
        if (header64_) put(s, std::uint64_t(v), big_);
        else put(s, std::uint32_t(v), big_);
    }
    Format format_;
    bool header64_, zlib_, big_;
    std::string appended_;
};

const std::vector<double> kPoints{0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1};

// Verts [4], Lines [0 1 2], Polys [0 1 2 3], Strips [0 1 3 2]; cell ids 0..3 in that order.
std::string polyData(XmlWriter& w) {
    // One statement per array: appended offsets follow the order of the calls,
    // which operands of a single '+' expression would leave unspecified.
    auto cells = [&](const char* tag, std::vector<double> conn, std::vector<double> off) {
        std::string c = std::string("<") + tag + ">\n";
        c += w.array("connectivity", "Int64", 1, conn);
        c += w.array("offsets", "Int64", 1, off);
        return c + "</" + tag + ">\n";
    };
    std::string b = "<Piece NumberOfPoints=\"5\" NumberOfVerts=\"1\" NumberOfLines=\"1\" NumberOfStrips=\"1\" NumberOfPolys=\"1\">\n";
    b += "<PointData Scalars=\"temp\">\n";
    b += w.array("temp", "Float64", 1, {10, 11, 12, 13, 14});
    b += w.array("vel", "Float32", 3, {3, 4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 6, 8, 0});
    b += "</PointData>\n<CellData>\n";
    b += w.array("id", "Int32", 1, {100, 101, 102, 103});
    b += w.array("flag", "UInt8", 1, {1, 2, 3, 4});
    b += "</CellData>\n<Points>\n";
    b += w.array("Points", "Float32", 3, kPoints);
    b += "</Points>\n";
    b += cells("Verts", {4}, {1});
    b += cells("Lines", {0, 1, 2}, {3});
    b += cells("Strips", {0, 1, 3, 2}, {4});
    b += cells("Polys", {0, 1, 2, 3}, {4});
    return w.file("PolyData", b + "</Piece>\n");
}

void checkPolyData(const std::vector<SceneObject>& objs) {
    ASSERT_EQ(objs.size(), 3u);
    const SceneObject &surf = objs[0], &lines = objs[1], &verts = objs[2];
    EXPECT_EQ(test::primitives(surf), 4u);
    EXPECT_EQ(surf.primitiveCell, (std::vector<std::uint32_t>{0, 0, 1, 1}));
    EXPECT_EQ(surf.field("id")->values, (std::vector<float>{102, 103}));
    EXPECT_EQ(surf.field("flag")->values, (std::vector<float>{3, 4}));
    EXPECT_EQ(surf.field("temp")->values, (std::vector<float>{10, 11, 12, 13}));
    EXPECT_EQ(test::primitives(lines), 2u);
    EXPECT_EQ(lines.field("id")->values, (std::vector<float>{101}));
    EXPECT_EQ(verts.field("id")->values, (std::vector<float>{100}));
    EXPECT_EQ(verts.field("vel")->values, (std::vector<float>{10}));
    EXPECT_EQ(verts.field("vel_0")->values, (std::vector<float>{6}));
    EXPECT_EQ(verts.vertices[0], 0.5f);
    EXPECT_EQ(verts.vertices[2], 1.f);
}

struct Variant {
    const char* label;
    Format format;
    bool header64, zlib, big;
};

}  // namespace

TEST(VtkXmlReader, PolyDataInEveryEncoding) {
    const Variant variants[] = {
        {"ascii", Format::Ascii, false, false, false},
        {"base64", Format::Binary, false, false, false},
        {"base64-uint64", Format::Binary, true, false, false},
        {"base64-zlib", Format::Binary, false, true, false},
        {"appended-raw", Format::Appended, true, false, false},
        {"appended-raw-zlib", Format::Appended, true, true, false},
        {"appended-base64", Format::AppendedBase64, false, false, false},
        {"appended-base64-zlib", Format::AppendedBase64, true, true, false},
        {"appended-raw-bigendian", Format::Appended, false, false, true},
        {"base64-zlib-bigendian", Format::Binary, true, true, true},
    };
    test::TempDir dir;
    for (const auto& v : variants) {
        SCOPED_TRACE(v.label);
        XmlWriter w(v.format, v.header64, v.zlib, v.big);
        const std::string path = dir.file(std::string(v.label) + ".vtp");
        test::writeText(path, polyData(w));
        checkPolyData(readMesh(path));
    }
}

TEST(VtkXmlReader, UnstructuredGridCellTypes) {
    XmlWriter w(Format::Appended, false, false);
    // triangle, quad, line, polyline, vertex, poly-vertex, tetra (skipped), strip
    const std::vector<double> types{5, 9, 3, 4, 1, 2, 10, 6};
    const std::vector<double> conn{0, 1, 2, 0, 1, 2, 3, 0, 1, 1, 2, 3, 4, 0, 4, 0, 1, 2, 4, 0, 1, 3, 2};
    const std::vector<double> ends{3, 7, 9, 12, 13, 15, 19, 23};
    std::string b = "<Piece NumberOfPoints=\"5\" NumberOfCells=\"8\">\n<Points>\n";
    b += w.array("Points", "Float64", 3, kPoints);
    b += "</Points>\n<Cells>\n";
    b += w.array("connectivity", "Int32", 1, conn);
    b += w.array("offsets", "Int32", 1, ends);
    b += w.array("types", "UInt8", 1, types);
    b += "</Cells>\n<CellData>\n";
    b += w.array("c", "Float32", 1, {0, 10, 20, 30, 40, 50, 60, 70});
    b += "</CellData>\n</Piece>\n";
    test::TempDir dir;
    test::writeText(dir.file("grid.vtu"), w.file("UnstructuredGrid", b));
    std::vector<std::string> warnings;
    const auto objs = readMesh(dir.file("grid.vtu"), &warnings);
    ASSERT_EQ(objs.size(), 3u);
    EXPECT_EQ(objs[0].primitiveCell, (std::vector<std::uint32_t>{0, 1, 1, 2, 2}));
    EXPECT_EQ(objs[0].field("c")->values, (std::vector<float>{0, 10, 70}));
    EXPECT_EQ(test::primitives(objs[1]), 3u);
    EXPECT_EQ(objs[1].primitiveCell, (std::vector<std::uint32_t>{0, 1, 1}));
    EXPECT_EQ(objs[1].field("c")->values, (std::vector<float>{20, 30}));
    EXPECT_EQ(test::primitives(objs[2]), 3u);
    EXPECT_EQ(objs[2].primitiveCell, (std::vector<std::uint32_t>{0, 1, 1}));
    EXPECT_EQ(objs[2].field("c")->values, (std::vector<float>{40, 50}));
    ASSERT_EQ(warnings.size(), 1u);
    EXPECT_NE(warnings[0].find("skipped 1 cells"), std::string::npos) << warnings[0];
}

TEST(VtkXmlReader, OnlyVolumeCellsIsAnError) {
    XmlWriter w(Format::Ascii, false, false);
    std::string b = "<Piece NumberOfPoints=\"4\" NumberOfCells=\"1\">\n<Points>\n" +
                    w.array("Points", "Float32", 3, {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}) + "</Points>\n<Cells>\n" +
                    w.array("connectivity", "Int32", 1, {0, 1, 2, 3}) + w.array("offsets", "Int32", 1, {4}) +
                    w.array("types", "UInt8", 1, {10}) + "</Cells>\n</Piece>\n";
    test::TempDir dir;
    test::writeText(dir.file("tet.vtu"), w.file("UnstructuredGrid", b));
    expectError([&] { readMesh(dir.file("tet.vtu")); }, {dir.file("tet.vtu"), "3D"});
}

TEST(VtkXmlReader, Fertility) {
    const std::string path = test::sharedData("meshes/fertility.vtu");
    if (path.empty()) GTEST_SKIP() << "../shared/data is absent; the real-file test needs meshes/fertility.vtu";
    std::vector<std::string> warnings;
    const auto objs = readMesh(path, &warnings);
    ASSERT_EQ(objs.size(), 1u);
    EXPECT_EQ(objs[0].representation, Representation::Surface);
    EXPECT_EQ(objs[0].vertexCount(), 5166u);
    EXPECT_EQ(test::primitives(objs[0]), 10344u);
    EXPECT_TRUE(warnings.empty());
    // Every point's norm lies in the file's stated L2_NORM_RANGE [7.369, 125.373].
    double lo = 1e30, hi = 0;
    const auto& v = objs[0].vertices;
    for (std::size_t i = 0; i < v.size(); i += 4) {
        const double n = length(Vec3(v[i], v[i + 1], v[i + 2]));
        lo = std::min(lo, n);
        hi = std::max(hi, n);
    }
    EXPECT_NEAR(lo, 7.3690286958, 1e-4);
    EXPECT_NEAR(hi, 125.37310342, 1e-3);
}

TEST(VtkXmlReader, CorruptBase64) {
    XmlWriter w(Format::Binary, false, false);
    std::string s = polyData(w);
    const std::size_t at = s.find("format=\"binary\">") + 22;
    s[at] = '*';
    test::TempDir dir;
    test::writeText(dir.file("b64.vtp"), s);
    expectError([&] { readMesh(dir.file("b64.vtp")); }, {dir.file("b64.vtp"), "corrupt base64"});
}

TEST(VtkXmlReader, WrongZlibStream) {
    XmlWriter w(Format::Appended, false, true);
    std::string s = polyData(w);
    // The first array (temp, 40 bytes) has 3 blocks: a 6-word (24-byte) table,
    // then the compressed blocks; overwrite bytes inside the first ones.
    const std::size_t data = s.find('_', s.find("<AppendedData")) + 1;
    for (std::size_t i = 30; i < 40; ++i) s[data + i] = char(0xA5);
    test::TempDir dir;
    test::writeText(dir.file("z.vtp"), s);
    expectError([&] { readMesh(dir.file("z.vtp")); }, {dir.file("z.vtp"), "DataArray 'temp'", "zlib"});
}

TEST(VtkXmlReader, UnsupportedDatasetMalformedXmlAndBadOffset) {
    test::TempDir dir;
    test::writeText(dir.file("img.vti"), "<VTKFile type=\"ImageData\"><ImageData/></VTKFile>");
    expectError([&] { readVtkXml(dir.file("img.vti")); }, {dir.file("img.vti") + ":1:", "unsupported dataset type 'ImageData'"});
    test::writeText(dir.file("bad.vtp"), "<VTKFile type=\"PolyData\">\n<PolyData>\n<Piece>\n</PolyData>\n</VTKFile>\n");
    expectError([&] { readMesh(dir.file("bad.vtp")); }, {dir.file("bad.vtp") + ":4:", "malformed XML"});
    XmlWriter w(Format::Appended, false, false);
    std::string s = polyData(w);
    s.replace(s.find("offset=\"0\""), 10, "offset=\"99999\"");
    test::writeText(dir.file("off.vtp"), s);
    expectError([&] { readMesh(dir.file("off.vtp")); }, {dir.file("off.vtp"), "DataArray 'temp'", "beyond"});
    XmlWriter a(Format::Ascii, false, false);
    s = polyData(a);
    s.replace(s.find("11.000000"), 9, "eleven");
    test::writeText(dir.file("txt.vtp"), s);
    expectError([&] { readMesh(dir.file("txt.vtp")); }, {dir.file("txt.vtp"), "DataArray 'temp'", "'eleven'"});
}
