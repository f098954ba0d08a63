// Writing an image as pycinema's .h5 (docs/formats.md, "pycinema's HDF5
// images"): built in memory with HDF5's core driver, then written atomically.
#include "h5_handle.h"
#include "h5_image.h"
#include "../src/io/stored_attributes.h"

#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/srgb.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace darkroom::h5 {

namespace {

// One dataset, gzip-compressed in chunks of up to 64 rows when it has pixels
// (as pycinema's writer compresses with gzip).
void addDataset(hid_t group, const std::string& name, const std::vector<hsize_t>& dims, hid_t type,
                const void* data) {
    Handle space(dims.empty() ? H5Screate(H5S_SCALAR) : H5Screate_simple(int(dims.size()), dims.data(), nullptr),
                 H5Sclose);
    Handle dcpl(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    if (dims.size() >= 2) {
        std::vector<hsize_t> chunk = dims;
        chunk[0] = std::min<hsize_t>(dims[0], 64);
        H5Pset_chunk(dcpl.get(), int(chunk.size()), chunk.data());
        H5Pset_deflate(dcpl.get(), 4);
    }
    Handle dataset(H5Dcreate2(group, name.c_str(), type, space.get(), H5P_DEFAULT, dcpl.get(), H5P_DEFAULT),
                   H5Dclose);
    if (!dataset.valid() || H5Dwrite(dataset.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
        throw Error(fmt::format("HDF5 could not write the dataset '{}'", name));
}

void addText(hid_t group, const std::string& name, const std::string& text) {
    // Fixed-length bytes in a one-element array, as pycinema writes text
    // (numpy 'S'), without its 10-byte cut.
    Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
    H5Tset_size(type.get(), std::max<std::size_t>(text.size(), 1));
    std::string padded = text.empty() ? std::string(1, '\0') : text;
    addDataset(group, name, {1}, type.get(), padded.data());
}

// HDF5 names cannot hold '/' and cannot be "."; such characters become '~'
// (as in entry file names).
std::string datasetName(std::string name) {
    std::replace(name.begin(), name.end(), '/', '~');
    return name.empty() || name == "." ? "~" : name;
}

// Near and far planes that map every finite depth into [0, 1): the nearest
// surface at 0, the farthest just below 1 (1.0 is pycinema's background).
std::pair<double, double> nearFarOf(const float* z, std::size_t n) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(z[i])) {
            lo = std::min(lo, double(z[i]));
            hi = std::max(hi, double(z[i]));
        }
    if (!(lo <= hi)) return {0.0, 1.0};
    const double span = hi > lo ? hi - lo : std::max(std::abs(hi), 1.0);
    return {lo, hi + span * 1e-3};
}

void writeDepth(hid_t channels, const float* z, std::size_t n, const std::vector<hsize_t>& dims,
                std::pair<double, double> nearFar) {
    std::vector<float> d(n);
    const double scale = 1.0 / (nearFar.second - nearFar.first);
    for (std::size_t i = 0; i < n; ++i)
        d[i] = std::isfinite(z[i]) ? float(std::clamp((double(z[i]) - nearFar.first) * scale, 0.0, 1.0)) : 1.f;
    addDataset(channels, "depth", dims, H5T_NATIVE_FLOAT, d.data());
}

// R, G, B (and A, else opaque) as pycinema's uint8 rgba, sRGB-encoded.
void writeRgba(hid_t channels, const Buffer& image, const std::vector<hsize_t>& dims) {
    const std::size_t n = image.pixelCount();
    const float* src[4] = {image.hostFloat("R"), image.hostFloat("G"), image.hostFloat("B"), image.hostFloat("A")};
    std::vector<unsigned char> rgba(n * 4);
    for (std::size_t i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c) {
            float v = src[c] ? src[c][i] : 1.f;
            if (c < 3) v = linearToSrgb(std::clamp(v, 0.f, 1.f));
            rgba[i * 4 + c] = (unsigned char)std::lround(std::clamp(std::isnan(v) ? 0.f : v, 0.f, 1.f) * 255.f);
        }
    addDataset(channels, "rgba", {dims[0], dims[1], 4}, H5T_NATIVE_UCHAR, rgba.data());
}

bool isColour(const Buffer& image, const std::string& c) {
    const bool rgb = image.hostFloat("R") && image.hostFloat("G") && image.hostFloat("B");
    return rgb && (c == "R" || c == "G" || c == "B" || c == "A");
}

std::optional<std::pair<double, double>> writeChannels(hid_t channels, const Buffer& image) {
    const std::vector<hsize_t> dims{hsize_t(image.height()), hsize_t(image.width())};
    std::optional<std::pair<double, double>> nearFar;
    if (image.hostFloat("R") && image.hostFloat("G") && image.hostFloat("B")) writeRgba(channels, image, dims);
    for (const auto& c : image.channels()) {
        if (isColour(image, c.name)) continue;
        if (c.name == "Z" && c.type == ChannelType::Float32) {
            nearFar = nearFarOf(image.hostFloat("Z"), image.pixelCount());
            writeDepth(channels, image.hostFloat("Z"), image.pixelCount(), dims, *nearFar);
        } else if (c.type == ChannelType::UInt32) {
            addDataset(channels, datasetName(c.name), dims, H5T_NATIVE_UINT32, image.hostUInt(c.name));
        } else {
            addDataset(channels, datasetName(c.name), dims, H5T_NATIVE_FLOAT, image.hostFloat(c.name));
        }
    }
    return nearFar;
}

void addNumbers(hid_t meta, const char* name, std::vector<double> values) {
    addDataset(meta, name, {hsize_t(values.size())}, H5T_NATIVE_DOUBLE, values.data());
}

void writeMeta(hid_t meta, const Buffer& image, std::optional<std::pair<double, double>> nearFar,
               const MetaValues& extra) {
    const float resolution[2] = {float(image.width()), float(image.height())};
    addDataset(meta, "resolution", {2}, H5T_NATIVE_FLOAT, resolution);
    std::vector<std::string> written{"resolution"};
    if (nearFar) addNumbers(meta, "CameraNearFar", {nearFar->first, nearFar->second});
    if (const auto& c = image.metadata().camera) {
        addNumbers(meta, "CameraPos", {c->position.x, c->position.y, c->position.z});
        addNumbers(meta, "CameraDir", {c->forward.x, c->forward.y, c->forward.z});
        addNumbers(meta, "CameraUp", {c->up.x, c->up.y, c->up.z});
        if (c->projection == Camera::Projection::Orthographic)
            addNumbers(meta, "CameraHeight", {c->viewHeight});
        else
            addNumbers(meta, "CameraAngle", {c->fovYDegrees});
    }
    auto free = [&](const std::string& name) {
        return name.rfind("Camera", 0) != 0 && std::find(written.begin(), written.end(), name) == written.end();
    };
    for (const auto& [key, value] : extra) {
        const std::string name = datasetName(key);
        if (!free(name)) continue;
        if (const double* v = std::get_if<double>(&value))
            addDataset(meta, name, {}, H5T_NATIVE_DOUBLE, v);
        else
            addText(meta, name, std::get<std::string>(value));
        written.push_back(name);
    }
    for (const auto& [key, text] : image.metadata().attributes)
        if (const std::string name = datasetName(key); isStoredAttribute(key) && free(name)) {
            addText(meta, name, text);
            written.push_back(name);
        }
}

}  // namespace

std::string encodeImage(const Buffer& image, const MetaValues& extra) {
    prepareLibrary();
    Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    if (!fapl.valid() || H5Pset_fapl_core(fapl.get(), 1 << 20, false) < 0)
        throw Error("HDF5 could not set up an in-memory file");
    Handle file(H5Fcreate(uniqueMemoryName("write").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl.get()), H5Fclose);
    if (!file.valid()) throw Error("HDF5 could not create an in-memory file");
    {
        Handle channels(H5Gcreate2(file.get(), "channels", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
        Handle meta(H5Gcreate2(file.get(), "meta", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose);
        if (!channels.valid() || !meta.valid()) throw Error("HDF5 could not create the groups channels and meta");
        const auto nearFar = writeChannels(channels.get(), image);
        writeMeta(meta.get(), image, nearFar, extra);
    }
    if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) throw Error("HDF5 could not finish the in-memory file");
    const ssize_t size = H5Fget_file_image(file.get(), nullptr, 0);
    if (size <= 0) throw Error("HDF5 could not give the file's bytes");
    std::string bytes(std::size_t(size), '\0');
    if (H5Fget_file_image(file.get(), bytes.data(), bytes.size()) != size)
        throw Error("HDF5 could not give the file's bytes");
    return bytes;
}

void writeImageFile(const Buffer& image, const std::string& path, const MetaValues& extra) {
    std::string bytes;
    try {
        bytes = encodeImage(image, extra);
    } catch (const Error& e) {
        throw Error(fmt::format("{}: {}", path, e.what()));
    }
    writeFileAtomic(path, bytes);
}

}  // namespace darkroom::h5
