// Reading one product by its extension (images, .npz arrays, .vti images).
#include <darkroom/error.h>
#include <darkroom/data/cinema/product.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/formats/vti.h>
#include <darkroom/data/image_io.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cstring>
#include <filesystem>

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

}  // namespace

std::shared_ptr<WritableBuffer> readCinemaProduct(const std::string& path, Diagnostics* warnings) {
    const std::string ext = extensionOf(path);
    if (ext == ".npz") return npzBuffer(path);
    if (ext == ".vti") {
        VtiImage image = readVti(path);
        if (warnings)
            for (auto& w : image.warnings) warnings->push_back(std::move(w));
        return std::move(image.buffer);
    }
    // Which product it is, whatever an earlier pipeline left in the file's
    // header: ColorMapping's database range finds the database from it.
    auto image = readImage(path);
    image->metadata().attributes["source"] = path;
    return image;
}

}  // namespace darkroom
