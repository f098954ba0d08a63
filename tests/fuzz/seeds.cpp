// Writes the binary seed corpora (EXR, PNG, TIFF, TGA, NPY, NPZ, VTI, H5 with the
// project's own writers; binary STL, PLY and legacy VTK byte by byte), so that no binary file is committed:
//   fuzz_seeds <folder>  ->  <folder>/<harness>/<seed>
// Text seeds are committed under tests/fuzz/corpus/<harness>/.
#include "h5_image.h"
#include "io/exr_file.h"
#include "../../framework/data/oiio/module.h"

#include <darkroom/buffer.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/formats/vti.h>
#include <darkroom/data/image_io.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <vector>

namespace fs = std::filesystem;
using namespace darkroom;

namespace {

// A small image whose pixels are not all alike (so compressors have work).
std::shared_ptr<WritableBuffer> image(int w, int h, std::vector<ChannelDesc> channels) {
    auto b = makeCpuBuffer(w, h, channels);
    for (const ChannelDesc& c : channels) {
        if (c.type == ChannelType::Float32) {
            float* p = b->writeFloat(c.name);
            for (int i = 0; i < w * h; ++i) p[i] = float(i % 7) / 7.0f + float(c.name.size());
        } else {
            std::uint32_t* p = b->writeUInt(c.name);
            for (int i = 0; i < w * h; ++i) p[i] = std::uint32_t(i * 3);
        }
    }
    return b;
}

void writeBytes(const fs::path& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

template <class T>
void put(std::string& s, T v) {
    s.append(reinterpret_cast<const char*>(&v), sizeof v);  // the hosts are little-endian, as STL is
}

// A binary STL: the 80-byte header, the count, then per triangle a normal,
// three vertices and the 16-bit attribute (50 bytes).
std::string binaryStl(std::string header, const std::vector<std::array<float, 9>>& triangles) {
    header.resize(80, ' ');
    put(header, std::uint32_t(triangles.size()));
    for (const auto& t : triangles) {
        for (float n : {0.f, 0.f, 1.f}) put(header, n);
        for (float v : t) put(header, v);
        put(header, std::uint16_t(0));
    }
    return header;
}

// A unit square of two triangles as binary little-endian PLY, with a point
// scalar and a face scalar.
std::string binaryTrianglePly() {
    std::string s =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
        "property float z\nproperty float height\nelement face 2\nproperty list uchar int vertex_indices\n"
        "property float quality\nend_header\n";
    const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (const auto& p : points) {
        for (float v : p) put(s, v);
        put(s, p[0] + p[1]);
    }
    const std::int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    for (const auto& f : faces) {
        put(s, std::uint8_t(3));
        for (std::int32_t i : f) put(s, i);
        put(s, 0.5f);
    }
    return s;
}

template <class T>
void putBigEndian(std::string& s, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    std::reverse(b, b + sizeof(T));  // legacy VTK's binary data is big-endian
    s.append(b, sizeof(T));
}

// The unit square of binaryTrianglePly() as a BINARY legacy VTK POLYDATA
// with a point scalar, in the classic cell layout or VTK 5.1's
// OFFSETS/CONNECTIVITY: what the direct reader (vtk_legacy/legacy_triangles.h) takes.
std::string binaryTriangleVtk(bool offsets) {
    std::string s = std::string("# vtk DataFile Version ") + (offsets ? "5.1" : "3.0") +
                    "\nsquare\nBINARY\nDATASET POLYDATA\nPOINTS 4 float\n";
    const float points[4][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
    for (const auto& p : points)
        for (float v : p) putBigEndian(s, v);
    const std::int32_t faces[2][3] = {{0, 1, 2}, {0, 2, 3}};
    if (offsets) {
        s += "\nPOLYGONS 3 6\nOFFSETS vtktypeint64\n";
        for (std::int64_t o : {0, 3, 6}) putBigEndian(s, o);
        s += "\nCONNECTIVITY vtktypeint64\n";
        for (const auto& f : faces)
            for (std::int32_t i : f) putBigEndian(s, std::int64_t(i));
    } else {
        s += "\nPOLYGONS 2 8\n";
        for (const auto& f : faces) {
            putBigEndian(s, std::int32_t(3));
            for (std::int32_t i : f) putBigEndian(s, i);
        }
    }
    s += "\nPOINT_DATA 4\nSCALARS height float 1\nLOOKUP_TABLE default\n";
    for (const auto& p : points) putBigEndian(s, p[0] + p[1]);
    return s + "\n";
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: fuzz_seeds <folder>\n";
        return 2;
    }
    const fs::path root = argv[1];
    for (const char* d : {"exr", "image", "npy", "npz", "vti", "stl", "h5", "ply", "vtk"}) fs::create_directories(root / d);
    try {
        // EXR: float RGBA with a camera-free G-buffer channel, each compression.
        const auto gbuffer = image(4, 3, {"R", "G", "B", "A", "Z", {"id", ChannelType::UInt32}});
        for (const char* compression : {"none", "zip", "zips", "piz", "rle"}) {
            ImageWriteOptions o;
            o.compression = compression;
            io::writeExr(*gbuffer, (root / "exr" / (std::string(compression) + ".exr")).string(), o);
        }
        // For the direct decoder (framework/data/src/io/exr_direct.h): half
        // channels, and three ZIP chunks of 16 lines, the last one short.
        {
            ImageWriteOptions o;
            o.halfFloat = true;
            io::writeExr(*gbuffer, (root / "exr" / "zip-half.exr").string(), o);
            const auto tall = image(5, 37, {"Z", "height"});
            io::writeExr(*tall, (root / "exr" / "zip-tall.exr").string(), ImageWriteOptions{});
        }
        // Found by the EXR harness: a string attribute declaring 1.9 GB
        // (framework/data/src/io/exr_attributes.h); kept as a seed.
        {
            std::ifstream in(root / "exr" / "none.exr", std::ios::binary);
            std::string exr((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            exr.insert(8, std::string("comments\0string\0\x8d\x5c\x63\x72" "abc", 23));
            writeBytes(root / "exr" / "lying-attribute", exr);
            // Found by the EXR harness after the preview check was added: a
            // preview whose 4 x width x height overflowed 64 bits (UBSan).
            std::string preview = exr.substr(0, 8) + std::string("preview\0preview\0\x08\0\0\0", 20) +
                                  std::string("\xff\xff\xff\xff\xff\xff\xff\xff", 8) + exr.substr(8);
            writeBytes(root / "exr" / "huge-preview", preview);
        }
        // Other formats through the OpenImageIO module. The harness takes the
        // first byte as the extension's index (see harnesses/image.cpp).
        const auto rgba = image(5, 4, {"R", "G", "B", "A"});
        const std::pair<const char*, char> formats[] = {{"png", 0}, {"tif", 1}, {"tga", 2}, {"hdr", 4}, {"ppm", 5}};
        for (const auto& [ext, index] : formats) {
            const fs::path tmp = root / "image" / (std::string("tmp.") + ext);
            oiio_module::writeImage(*rgba, tmp.string(), ImageWriteOptions{});
            std::ifstream in(tmp, std::ios::binary);
            const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            writeBytes(root / "image" / ext, std::string(1, index) + bytes);
            fs::remove(tmp);
        }
        // Found by the image harness: a tEXt chunk declaring 1.9 GB in a
        // 200-byte PNG (framework/data/oiio/png_chunks.h); kept as a seed.
        {
            std::ifstream in(root / "image" / "png", std::ios::binary);
            std::string png((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
            const std::string lying("\x73\x6d\x65\x74tEXtComment\0", 16);
            png.insert(1 + 8 + 25, lying);  // after the selector byte, signature and IHDR
            writeBytes(root / "image" / "png-lying-text-chunk", png);
        }
        // NPY: C and Fortran order; NPZ: stored and deflated.
        NpyArray a{"data", "<f4", {2, 3}, false, {1, 2, 3, 4, 5, 6}};
        writeBytes(root / "npy" / "c-order.npy", encodeNpy(a));
        NpyArray f = a;
        f.fortranOrder = true;
        writeBytes(root / "npy" / "fortran-order.npy", encodeNpy(f));
        NpyArray depth{"depth", "<f4", {1, 2, 2}, false, {0.5f, 1, 2, 3}};
        writeNpz((root / "npz" / "stored.npz").string(), {a, depth}, false);
        writeNpz((root / "npz" / "deflated.npz").string(), {a, depth}, true);
        // VTI: appended raw, base64 and zlib, with a TTK camera.
        const auto vtiImage = image(3, 2, {"Z", "Scalar"});
        TtkCamera camera;
        camera.width = 3;
        camera.height = 2;
        writeVti((root / "vti" / "raw.vti").string(), *vtiImage, camera);
        writeVti((root / "vti" / "base64.vti").string(), *vtiImage, camera, {.base64 = true});
        writeVti((root / "vti" / "zlib.vti").string(), *vtiImage, std::nullopt, {.base64 = true, .zlib = true});
        // pycinema's .h5: depth, a scalar, colour and ids with a camera and a row in meta.
        auto h5Image = image(3, 2, {"Z", "Scalar", "R", "G", "B"});
        Camera h5Camera;
        h5Camera.width = 3;
        h5Camera.height = 2;
        h5Image->metadata().camera = h5Camera;
        writeBytes(root / "h5" / "image.h5", h5::encodeImage(*h5Image, {{"time", 0.5}, {"label", std::string("a")}}));
        // Binary STL: one triangle (134 bytes), and two sharing an edge under
        // a header that starts with "solid" as CAD tools write it.
        writeBytes(root / "stl" / "one-triangle.stl", binaryStl("binary", {{0, 0, 0, 1, 0, 0, 0, 1, 0}}));
        writeBytes(root / "stl" / "solid-header.stl",
                   binaryStl("solid exported", {{0, 0, 0, 1, 0, 0, 0, 1, 0}, {1, 0, 0, 1, 1, 0, 0, 1, 0}}));
        // Binary PLY of triangles: what the direct reader (ply/ply_triangles.h) takes.
        writeBytes(root / "ply" / "binary-triangles.ply", binaryTrianglePly());
        // Binary legacy VTK of triangles, both cell layouts: what the direct
        // reader (vtk_legacy/legacy_triangles.h) takes.
        writeBytes(root / "vtk" / "binary-triangles.vtk", binaryTriangleVtk(false));
        writeBytes(root / "vtk" / "binary-triangles-5.1.vtk", binaryTriangleVtk(true));
    } catch (const std::exception& e) {
        std::cerr << "fuzz_seeds: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
