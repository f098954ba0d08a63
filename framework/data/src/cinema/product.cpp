// Reading one product by its extension (images, .npz arrays, .vti images),
// and telling the products that are geometry (meshes, volumes) from images.
#include "../io/optional_module.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/data/formats/vti.h>
#include <darkroom/data/formats/xml_document.h>
#include <darkroom/data/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace darkroom {

namespace {

std::string extensionOf(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    for (char& c : e) c = char(std::tolower(static_cast<unsigned char>(c)));
    return e;
}

std::shared_ptr<WritableBuffer> npzBuffer(const std::string& path) {
    const auto arrays = readNpz(path);
    const auto& first = arrays.front();
    if (first.shape.size() != 2 && first.shape.size() != 3)
        throw Error(fmt::format("{}:{}.npy: shape has {} dimensions; expected an image (rows, columns) or "
                                "(rows, columns, components)",
                                path, first.name, first.shape.size()));
    const std::size_t h = first.shape[0], w = first.shape[1];
    if (h == 0 || w == 0 || h > (1u << 20) || w > (1u << 20))
        throw Error(fmt::format("{}:{}.npy: image size {} x {} is not usable", path, first.name, w, h));
    std::vector<ChannelDesc> channels;
    for (const auto& a : arrays) {
        if (a.shape.size() < 2 || a.shape[0] != h || a.shape[1] != w)
            throw Error(fmt::format("{}:{}.npy: shape differs from the first member's ({} x {}); every member "
                                    "must be an image of one size",
                                    path, a.name, h, w));
        const std::size_t k = a.shape.size() == 3 ? a.shape[2] : 1;
        if (a.shape.size() > 3 || k == 0)
            throw Error(fmt::format("{}:{}.npy: expected (rows, columns) or (rows, columns, k)", path, a.name));
        for (std::size_t c = 0; c < k; ++c)
            channels.push_back({a.shape.size() == 3 ? fmt::format("{}.{}", a.name, c) : a.name, ChannelType::Float32});
    }
    auto out = makeCpuBuffer(int(w), int(h), channels);
    std::size_t ch = 0;
    for (const auto& a : arrays) {
        const std::size_t k = a.shape.size() == 3 ? a.shape[2] : 1;
        for (std::size_t c = 0; c < k; ++c, ++ch) {
            float* dst = out->writeFloat(channels[ch].name);
            for (std::size_t i = 0; i < w * h; ++i) dst[i] = a.values[i * k + c];
        }
    }
    out->metadata().attributes["source"] = path;
    return out;
}

// The points along each axis of a .vti's WholeExtent; nullopt when it has
// none that reads as six integers.
std::optional<std::array<long long, 3>> vtiPoints(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "product");
    const mesh::VtkXmlDocument doc = mesh::parseVtkXml(data, path);
    const mesh::XmlElement* image = doc.root ? doc.root->child("ImageData") : nullptr;
    if (!image) return std::nullopt;
    std::istringstream in(image->attributeOr("WholeExtent", ""));
    // int, as VTK's extents are: a larger number fails to read, so the sizes cannot overflow.
    std::array<int, 6> e{};
    for (int& v : e)
        if (!(in >> v)) return std::nullopt;
    return std::array<long long, 3>{1LL + e[1] - e[0], 1LL + e[3] - e[2], 1LL + e[5] - e[4]};
}

// The dataset type of a legacy .vtk ("STRUCTURED_POINTS"), from the fourth
// line of its header; "" when the file does not start like one.
std::string legacyDataset(const std::string& path) {
    requireRegularFile(path, "product");
    std::ifstream in(path, std::ios::binary);
    std::string line;
    // Version, title, ASCII or BINARY, then DATASET (each at most 256 bytes in VTK's writers).
    for (int i = 0; i < 4; ++i)
        if (!std::getline(in, line) || (i == 0 && line.rfind("# vtk DataFile", 0) != 0)) return "";
    std::istringstream words(line);
    std::string keyword, type;
    words >> keyword >> type;
    return keyword == "DATASET" ? type : "";
}

// Throws the InputError that says what to do with a mesh or a volume;
// returns for anything else (and when the file cannot tell: the reader's
// own error then says more).
void refuseGeometry(const std::string& path) {
    std::optional<GeometryProduct> g;
    try {
        g = geometryProduct(path);
    } catch (const Error&) {
        return;
    }
    if (g) throw InputError(fmt::format("{}: {}, not an image. {}", path, g->what, g->advice));
}

}  // namespace

bool isVtkProduct(const std::string& path) {
    const std::string ext = extensionOf(path);
    for (const char* e : {".vti", ".vtk", ".vtu", ".vtp", ".pvtu", ".pvtp"})
        if (ext == e) return true;
    return false;
}

std::optional<GeometryProduct> geometryProduct(const std::string& path) {
    if (!isVtkProduct(path)) return std::nullopt;
    const std::string ext = extensionOf(path);
    const std::string capture = fmt::format(
        "Darkroom shades images: capture it into G-buffers with `darkroom capture SCENE -o DB.cdb`, SCENE naming "
        "it as an object (objects: [{{file: {}}}]; docs/scene-format.md), and shade DB.cdb",
        std::filesystem::absolute(path).lexically_normal().string());
    if (ext == ".vti") {
        // A 2-D .vti is an image (TTK's); one with two or more points along every axis is a volume.
        const auto n = vtiPoints(path);
        if (!n || (*n)[0] < 2 || (*n)[1] < 2 || (*n)[2] < 2) return std::nullopt;
        return GeometryProduct{fmt::format("a volume (VTK ImageData of {} x {} x {} points)", (*n)[0], (*n)[1], (*n)[2]),
                               capture};
    }
    if (ext == ".vtk") {
        const std::string dataset = legacyDataset(path);
        if (dataset.empty()) return std::nullopt;
        if (dataset == "POLYDATA") return GeometryProduct{"a mesh (VTK legacy POLYDATA)", capture};
        // The scene reader takes only POLYDATA from legacy files (docs/scene-format.md).
        return GeometryProduct{fmt::format("VTK legacy {} data (a grid or volume)", dataset),
                               "Darkroom shades images, and `darkroom capture` draws volumes from .vti and .vtu "
                               "files but not from legacy .vtk ones: convert it (ParaView, meshio) and capture that "
                               "(docs/scene-format.md, Volumes)"};
    }
    return GeometryProduct{fmt::format("a mesh or a volume (VTK XML {})", ext), capture};
}

std::shared_ptr<WritableBuffer> readCinemaProduct(const std::string& path, Diagnostics* warnings) {
    const std::string ext = extensionOf(path);
    if (ext == ".npz") return npzBuffer(path);
    if (ext == ".h5") {
        h5::Image image = io::h5Module("reading '" + path + "'").readImageFile(path);
        if (warnings)
            for (auto& w : image.warnings) warnings->push_back(std::move(w));
        return std::move(image.buffer);
    }
    if (ext == ".vti") {
        // TTK's 2-D images are the common case: read first, and only a
        // failure asks whether the file is a volume.
        VtiImage image;
        try {
            image = readVti(path);
        } catch (const Error&) {
            refuseGeometry(path);
            throw;
        }
        if (warnings)
            for (auto& w : image.warnings) warnings->push_back(std::move(w));
        return std::move(image.buffer);
    }
    if (isVtkProduct(path)) refuseGeometry(path);
    // Which product it is, whatever an earlier pipeline left in the file's
    // header: ColorMapping's database range finds the database from it.
    auto image = readImage(path);
    image->metadata().attributes["source"] = path;
    return image;
}

}  // namespace darkroom
