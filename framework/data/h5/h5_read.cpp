// Reading pycinema's .h5 images (docs/formats.md, "pycinema's HDF5 images"):
// the file is opened from memory (HDF5's core driver), its `channels` listed
// and checked before a pixel is allocated, then read into one buffer.
#include "h5_image.h"
#include "h5_read_parts.h"
#include "../src/formats/ttk_depth.h"

#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/limits.h>
#include <darkroom/srgb.h>

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>

namespace darkroom::h5 {

namespace {

constexpr hsize_t kMaxComponents = 64;

bool sameLetters(const std::string& a, const char* b) {
    return std::equal(a.begin(), a.end(), b, b + std::strlen(b),
                      [](char x, char y) { return std::tolower((unsigned char)x) == std::tolower((unsigned char)y); });
}

// How one dataset of `channels` becomes buffer channels.
struct Planned {
    enum class Kind { Depth, Rgba, UInt, Float } kind = Kind::Float;
    std::string dataset;
    std::size_t components = 1;
    bool eightBit = false;  // rgba stored as 8-bit code values (pycinema's uint8)
    std::vector<ChannelDesc> channels;
};

Planned plan(const std::string& dataset, const DatasetInfo& info, const std::string& where) {
    if (info.typeClass != H5T_INTEGER && info.typeClass != H5T_FLOAT)
        throw InputError(fmt::format("{}: datatype class {} (strings, enums and compounds are not images); expected "
                                     "integers or floats",
                                     where, int(info.typeClass)));
    if (info.rank != 2 && info.rank != 3)
        throw InputError(fmt::format("{}: {} dimensions; expected an image (rows, columns) or (rows, columns, k)",
                                     where, info.rank));
    Planned p;
    p.dataset = dataset;
    p.components = info.rank == 3 ? std::size_t(info.dims[2]) : 1;
    if (p.components == 0 || p.components > kMaxComponents)
        throw InputError(fmt::format("{}: {} components; expected 1 to {}", where, p.components, kMaxComponents));
    if (info.rank == 3 && sameLetters(dataset, "rgba") && (p.components == 3 || p.components == 4)) {
        p.kind = Planned::Kind::Rgba;
        p.eightBit = info.typeClass == H5T_INTEGER && info.typeSize == 1;
        for (const char* c : {"R", "G", "B", "A"})
            if (p.channels.size() < p.components) p.channels.push_back({c});
    } else if (info.rank == 2 && sameLetters(dataset, "depth")) {
        p.kind = Planned::Kind::Depth;
        p.channels.push_back({"Z"});
    } else if (info.rank == 2 && info.unsignedInteger && info.typeSize == 4) {
        p.kind = Planned::Kind::UInt;  // ids, as Darkroom writes them
        p.channels.push_back({dataset, ChannelType::UInt32});
    } else {
        for (std::size_t c = 0; c < p.components; ++c)
            p.channels.push_back({info.rank == 3 ? fmt::format("{}.{}", dataset, c) : dataset});
    }
    return p;
}

struct Layout {
    std::vector<Planned> planned;
    int width = 0, height = 0;
};

Layout planChannels(hid_t channels, const std::string& name, Diagnostics& warnings) {
    Layout layout;
    std::uint64_t bytes = 0;
    for (const std::string& dataset : datasetNames(channels, name + ": channels", warnings)) {
        const std::string where = fmt::format("{}: channels/{}", name, dataset);
        Handle d(H5Dopen2(channels, dataset.c_str(), H5P_DEFAULT), H5Dclose);
        if (!d.valid()) throw InputError(where + ": the dataset cannot be opened");
        const DatasetInfo info = inspectDataset(d.get(), where);
        Planned p = plan(dataset, info, where);
        const hsize_t rows = info.dims[0], columns = info.dims[1];
        if (layout.planned.empty()) {
            if (rows == 0 || columns == 0 || rows > (1u << 20) || columns > (1u << 20))
                throw InputError(fmt::format("{}: image size {} x {} (width x height) is not usable; expected 1 to "
                                             "2^20 pixels each way",
                                             where, columns, rows));
            checkImagePixels(columns, rows, where);
            layout.width = int(columns);
            layout.height = int(rows);
        } else if (rows != hsize_t(layout.height) || columns != hsize_t(layout.width)) {
            throw InputError(fmt::format("{}: {} x {} (width x height), but channels/{} is {} x {}; every channel "
                                         "must be one size",
                                         where, columns, rows, layout.planned.front().dataset, layout.width,
                                         layout.height));
        }
        bytes += std::uint64_t(rows) * columns * p.components * 4;
        checkBytes(Limit::DecodedBytes, bytes, where, "the channels read so far");
        layout.planned.push_back(std::move(p));
    }
    if (layout.planned.empty())
        throw InputError(fmt::format("{}: the group channels holds no dataset; expected at least one image", name));
    return layout;
}

std::vector<float> readFloats(hid_t channels, const Planned& p, std::size_t count, const std::string& name) {
    std::vector<float> values(count);
    Handle d(H5Dopen2(channels, p.dataset.c_str(), H5P_DEFAULT), H5Dclose);
    if (!d.valid() || H5Dread(d.get(), H5T_NATIVE_FLOAT, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw InputError(fmt::format("{}: channels/{}: the values cannot be read (damaged, or compressed with a "
                                     "filter this HDF5 lacks)",
                                     name, p.dataset));
    return values;
}

void readUInt(hid_t channels, const Planned& p, WritableBuffer& out, const std::string& name) {
    Handle d(H5Dopen2(channels, p.dataset.c_str(), H5P_DEFAULT), H5Dclose);
    std::uint32_t* dst = out.writeUInt(p.channels.front().name);
    if (!d.valid() || H5Dread(d.get(), H5T_NATIVE_UINT32, H5S_ALL, H5S_ALL, H5P_DEFAULT, dst) < 0)
        throw InputError(fmt::format("{}: channels/{}: the values cannot be read", name, p.dataset));
}

// Values of one planned dataset into its channels; 8-bit rgba decoded from
// sRGB (alpha linear), depth kept as stored (converted once meta is known).
void fill(const Planned& p, const std::vector<float>& values, WritableBuffer& out) {
    const std::size_t n = out.pixelCount(), k = p.components;
    for (std::size_t c = 0; c < p.channels.size(); ++c) {
        float* dst = out.writeFloat(p.channels[c].name);
        const bool colour = p.kind == Planned::Kind::Rgba && c < 3;
        for (std::size_t i = 0; i < n; ++i) {
            float v = values[i * k + c];
            if (p.eightBit) v = colour ? srgbToLinear(v / 255.f) : v / 255.f;
            dst[i] = v;
        }
    }
}

// pycinema's and the ParaView plugin's depth: normalised to [0,1] between the
// camera's near and far planes, 1.0 = background. With meta/CameraNearFar it
// becomes planar world depth; without, values in [0,1] are kept (1.0 -> +inf)
// and a warning says so; any other values are taken as planar depth as they are.
void convertDepth(float* z, std::size_t n, const MetaValuesRead& meta, WritableBuffer& out, const std::string& name,
                  Diagnostics& warnings) {
    const auto nf = meta.numbers.find("CameraNearFar");
    const bool haveNearFar = nf != meta.numbers.end() && nf->second.size() == 2 && std::isfinite(nf->second[0]) &&
                             std::isfinite(nf->second[1]) && nf->second[0] < nf->second[1];
    bool normalised = true;
    for (std::size_t i = 0; i < n && normalised; ++i) normalised = std::isnan(z[i]) || (z[i] >= 0.f && z[i] <= 1.f);
    std::string& convention = out.metadata().attributes["depth.convention"];
    if (haveNearFar) {
        for (std::size_t i = 0; i < n; ++i) z[i] = formats::planarFromTtkDepth(z[i], nf->second[0], nf->second[1]);
        convention = fmt::format("normalised depth; Z = near + d (far - near) with near {} far {}; 1.0 background -> "
                                 "+inf",
                                 nf->second[0], nf->second[1]);
    } else if (normalised) {
        for (std::size_t i = 0; i < n; ++i)
            if (std::isnan(z[i]) || z[i] >= 1.f) z[i] = std::numeric_limits<float>::infinity();
        convention = "normalised depth kept in [0,1) (no meta/CameraNearFar); 1.0 background -> +inf";
        warnings.push_back({Diagnostic::Severity::Warning, name,
                            "depth lies in [0,1] and meta has no CameraNearFar: Z keeps the normalised values "
                            "(ordering preserved; not world units) and the 1.0 background becomes +inf",
                            {}});
    } else {
        for (std::size_t i = 0; i < n; ++i)
            if (std::isnan(z[i])) z[i] = std::numeric_limits<float>::infinity();
        convention = "planar depth kept as is; NaN -> +inf";
    }
}

Handle openMemoryFile(std::string_view bytes, const std::string& name) {
    if (bytes.empty()) throw InputError(fmt::format("{}: an empty file; expected an HDF5 file", name));
    Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
    // No backing store: nothing is ever written to or read from disk by HDF5.
    if (!fapl.valid() || H5Pset_fapl_core(fapl.get(), 1 << 16, false) < 0 ||
        H5Pset_file_image(fapl.get(), const_cast<char*>(bytes.data()), bytes.size()) < 0)
        throw Error(fmt::format("{}: HDF5 could not take the file's bytes", name));
    Handle file(H5Fopen(uniqueMemoryName("read").c_str(), H5F_ACC_RDONLY, fapl.get()), H5Fclose);
    if (!file.valid())
        throw InputError(fmt::format("{}: not an HDF5 file, or a damaged one; expected pycinema's .h5 layout (groups "
                                     "channels and meta)",
                                     name));
    return file;
}

}  // namespace

Image readImage(std::string_view bytes, const std::string& name) {
    prepareLibrary();
    Handle file = openMemoryFile(bytes, name);
    Image result;
    if (H5Lexists(file.get(), "channels", H5P_DEFAULT) <= 0)
        throw InputError(fmt::format("{}: no group 'channels'; expected pycinema's .h5 layout (groups channels and "
                                     "meta)",
                                     name));
    Handle channels(H5Gopen2(file.get(), "channels", H5P_DEFAULT), H5Gclose);
    if (!channels.valid()) throw InputError(fmt::format("{}: channels is not a group; expected pycinema's layout", name));
    const Layout layout = planChannels(channels.get(), name, result.warnings);
    const MetaValuesRead meta = readMeta(file.get(), name, result.warnings);
    std::vector<ChannelDesc> descs;
    for (const auto& p : layout.planned) descs.insert(descs.end(), p.channels.begin(), p.channels.end());
    for (std::size_t i = 0; i < descs.size(); ++i)
        for (std::size_t j = 0; j < i; ++j)
            if (descs[i].name == descs[j].name)
                throw InputError(fmt::format("{}: two datasets of channels give the channel '{}'", name, descs[i].name));
    auto out = makeCpuBuffer(layout.width, layout.height, descs);
    const std::size_t n = out->pixelCount();
    for (const auto& p : layout.planned) {
        if (p.kind == Planned::Kind::UInt) {
            readUInt(channels.get(), p, *out, name);
            continue;
        }
        fill(p, readFloats(channels.get(), p, n * p.components, name), *out);
        if (p.kind == Planned::Kind::Depth) convertDepth(out->writeFloat("Z"), n, meta, *out, name, result.warnings);
    }
    applyMeta(meta, *out, name, result.warnings);
    out->metadata().attributes["source"] = name;
    result.buffer = std::move(out);
    return result;
}

Image readImageFile(const std::string& path) {
    return readImage(readInputFile(path, "product"), path);
}

}  // namespace darkroom::h5
