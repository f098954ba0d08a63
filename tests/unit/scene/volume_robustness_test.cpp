// Corrupted and truncated copies of valid volume files: readVolume and every
// representation must succeed or throw darkroom::Error naming the file, never
// crash. Deterministic (fixed seed), like reader_robustness_test.cpp.
#include "mesh_test_files.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/scene/volume.h>

#include <gtest/gtest.h>

#include <random>

using namespace darkroom;

namespace {

// One cell of each 3D type (tetra, hexahedron, wedge, pyramid) side by side,
// appended raw binary, with a point and a cell array.
std::string appendedVtu() {
    std::vector<float> pts;
    for (int i = 0; i < 12; ++i)
        for (float v : {float(i % 4), float(i / 4 % 2), float(i / 8)}) pts.push_back(v);
    const std::vector<std::int64_t> conn{0, 1, 4, 8, 0, 1, 5, 4, 8, 9, 5, 4, 1, 2, 6, 9, 10, 5, 2, 3, 7, 6, 11};
    const std::vector<std::int64_t> off{4, 12, 18, 23};
    const std::vector<std::uint8_t> types{10, 12, 13, 14};
    std::vector<float> f;
    for (int i = 0; i < 12; ++i) f.push_back(float(i % 4) * 0.3f + float(i / 8));
    const std::vector<std::int32_t> c{1, 2, 3, 4};
    std::string data;
    std::vector<std::size_t> at;
    for (const std::string& a : {test::bytesOf(pts), test::bytesOf(conn), test::bytesOf(off), test::bytesOf(types),
                                 test::bytesOf(f), test::bytesOf(c)}) {
        at.push_back(data.size());
        test::put(data, std::uint64_t(a.size()), false);
        data += a;
    }
    auto arr = [&](const char* type, const char* name, int comps, int k) {
        return std::string("<DataArray type=\"") + type + "\" Name=\"" + name + "\" NumberOfComponents=\"" +
               std::to_string(comps) + "\" format=\"appended\" offset=\"" + std::to_string(at[std::size_t(k)]) + "\"/>\n";
    };
    return "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n"
           "<UnstructuredGrid><Piece NumberOfPoints=\"12\" NumberOfCells=\"4\">\n<PointData>" +
           arr("Float32", "f", 1, 4) + "</PointData><CellData>" + arr("Int32", "c", 1, 5) + "</CellData>\n<Points>" +
           arr("Float32", "p", 3, 0) + "</Points>\n<Cells>" + arr("Int64", "connectivity", 1, 1) +
           arr("Int64", "offsets", 1, 2) + arr("UInt8", "types", 1, 3) +
           "</Cells></Piece></UnstructuredGrid>\n<AppendedData encoding=\"raw\">_" + data + "\n</AppendedData></VTKFile>\n";
}

std::string asciiVti() {
    return "<VTKFile type=\"ImageData\" version=\"1.0\">\n<ImageData WholeExtent=\"0 2 0 1 0 1\" Origin=\"0 0 0\" "
           "Spacing=\"1 1 1\">\n<Piece Extent=\"0 2 0 1 0 1\"><PointData>\n<DataArray type=\"Float32\" Name=\"f\" "
           "format=\"ascii\">0 1 2 1 2 3 2 3 4 3 4 5</DataArray>\n</PointData></Piece>\n</ImageData></VTKFile>\n";
}

void drawAll(const VolumeMesh& v) {
    VolumeRepresentation boundary, iso, slice;
    iso.kind = VolumeRepresentation::Kind::Isosurface;
    iso.contourBy = "f";
    iso.isovalues = {0.7, 1.5};
    slice.kind = VolumeRepresentation::Kind::Slice;
    slice.planes = {{{0.5, 0.5, 0.5}, {1, 1, 1}}};
    for (const auto* r : {&boundary, &iso, &slice}) volumeSurface(v, *r, "o");
}

void fuzz(const std::string& name, const std::string& valid) {
    test::TempDir dir;
    const std::string path = dir.file(name);
    test::writeText(path, valid);
    ASSERT_NO_THROW(drawAll(readVolume(path))) << name << " must be valid before it is corrupted";
    std::mt19937 rng(4242);
    int errors = 0;
    for (int round = 0; round < 300; ++round) {
        std::string s = valid;
        if (round % 4 == 0) {
            s.resize(rng() % s.size());
        } else {
            const int flips = 1 + int(rng() % 4);
            for (int k = 0; k < flips; ++k) {
                const std::size_t i = rng() % s.size();
                const int kind = int(rng() % 3);
                s[i] = kind == 0 ? char(rng()) : kind == 1 ? char('0' + rng() % 10) : char(0xff);
            }
        }
        test::writeText(path, s);
        try {
            drawAll(readVolume(path));
        } catch (const Error& e) {
            ++errors;
            EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
        } catch (const std::exception& e) {
            ADD_FAILURE() << name << " round " << round << ": non-darkroom exception: " << e.what();
        }
    }
    EXPECT_GT(errors, 30) << "most corruptions of " << name << " should be detected";
}

}  // namespace

TEST(VolumeRobustness, AppendedVtuWithEveryCellType) { fuzz("v.vtu", appendedVtu()); }
TEST(VolumeRobustness, AsciiVti) { fuzz("v.vti", asciiVti()); }
