// The `meta` group of an .h5 image: pycinema keeps an image's parameters and
// metadata there (one dataset each), the ParaView plugin the resolution and
// its camera (CameraPos, CameraDir, CameraUp, CameraHeight, CameraNearFar).
#include "h5_read_parts.h"

#include <darkroom/error.h>

#include <fmt/format.h>

#include <cmath>
#include <cstring>
#include <optional>

namespace darkroom::h5 {

namespace {

constexpr hsize_t kMaxMetaNumbers = 16;       // a camera vector, a near/far pair; larger arrays are not metadata
constexpr std::size_t kMaxTextBytes = 65536;  // one text value

std::vector<double> readNumbers(hid_t dataset, const DatasetInfo& info, const std::string& where) {
    std::vector<double> values(info.elements);
    if (H5Dread(dataset, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()) < 0)
        throw InputError(fmt::format("{}: the values cannot be read", where));
    return values;
}

std::string readText(hid_t dataset, const DatasetInfo& info, const std::string& where) {
    Handle memType(H5Tcopy(H5T_C_S1), H5Tclose);
    if (info.variableString) {
        // h5py's str: a variable-length string, freed by HDF5's own reclaim.
        H5Tset_size(memType.get(), H5T_VARIABLE);
        char* value = nullptr;
        if (H5Dread(dataset, memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, &value) < 0)
            throw InputError(fmt::format("{}: the text cannot be read", where));
        std::string text = value ? std::string(value, strnlen(value, kMaxTextBytes)) : std::string();
        Handle space(H5Dget_space(dataset), H5Sclose);
        H5Dvlen_reclaim(memType.get(), space.get(), H5P_DEFAULT, &value);
        return text;
    }
    // pycinema's numpy bytes ('S10'): fixed length, padded with NULs.
    if (info.typeSize == 0 || info.typeSize > kMaxTextBytes)
        throw InputError(fmt::format("{}: a text of {} bytes; expected at most {}", where, info.typeSize,
                                     kMaxTextBytes));
    H5Tset_size(memType.get(), info.typeSize);
    std::string text(info.typeSize, '\0');
    if (H5Dread(dataset, memType.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0)
        throw InputError(fmt::format("{}: the text cannot be read", where));
    text.resize(strnlen(text.data(), text.size()));
    return text;
}

std::optional<Vec3> vec3(const MetaValuesRead& meta, const char* key) {
    const auto it = meta.numbers.find(key);
    if (it == meta.numbers.end() || it->second.size() != 3) return std::nullopt;
    return Vec3{it->second[0], it->second[1], it->second[2]};
}

std::optional<double> single(const MetaValuesRead& meta, const char* key) {
    const auto it = meta.numbers.find(key);
    if (it == meta.numbers.end() || it->second.size() != 1 || !std::isfinite(it->second[0])) return std::nullopt;
    return it->second[0];
}

// The camera, when meta has a position and a direction and either a view
// height (the ParaView plugin's orthographic cameras) or an angle (Darkroom's
// perspective ones).
std::optional<Camera> cameraOf(const MetaValuesRead& meta, int width, int height) {
    const auto position = vec3(meta, "CameraPos"), direction = vec3(meta, "CameraDir");
    const auto viewHeight = single(meta, "CameraHeight"), angle = single(meta, "CameraAngle");
    if (!position || !direction || (!viewHeight && !angle) || length(*direction) == 0.0) return std::nullopt;
    Camera c;
    c.position = *position;
    c.forward = normalize(*direction);
    c.up = vec3(meta, "CameraUp").value_or(Vec3{0, 1, 0});
    if (angle) {
        c.projection = Camera::Projection::Perspective;
        c.fovYDegrees = *angle;
    } else {
        c.projection = Camera::Projection::Orthographic;
        c.viewHeight = *viewHeight;
    }
    c.width = width;
    c.height = height;
    return c;
}

bool isLayoutKey(const std::string& key) {
    return key == "resolution" || key.rfind("Camera", 0) == 0;
}

}  // namespace

MetaValuesRead readMeta(hid_t file, const std::string& name, Diagnostics& warnings) {
    MetaValuesRead meta;
    if (H5Lexists(file, "meta", H5P_DEFAULT) <= 0) return meta;
    Handle group(H5Gopen2(file, "meta", H5P_DEFAULT), H5Gclose);
    if (!group.valid()) throw InputError(fmt::format("{}: meta is not a group; expected pycinema's layout", name));
    for (const std::string& key : datasetNames(group.get(), name + ": meta", warnings)) {
        const std::string where = fmt::format("{}: meta/{}", name, key);
        Handle dataset(H5Dopen2(group.get(), key.c_str(), H5P_DEFAULT), H5Dclose);
        if (!dataset.valid()) throw InputError(where + ": the dataset cannot be opened");
        const DatasetInfo info = inspectDataset(dataset.get(), where);
        const bool number = info.typeClass == H5T_INTEGER || info.typeClass == H5T_FLOAT;
        if (number && info.elements <= kMaxMetaNumbers)
            meta.numbers[key] = readNumbers(dataset.get(), info, where);
        else if (info.typeClass == H5T_STRING && info.elements == 1)
            meta.texts[key] = readText(dataset.get(), info, where);
    }
    return meta;
}

void applyMeta(const MetaValuesRead& meta, WritableBuffer& out, const std::string& name, Diagnostics& warnings) {
    const auto res = meta.numbers.find("resolution");
    if (res != meta.numbers.end() &&
        (res->second.size() != 2 || res->second[0] != out.width() || res->second[1] != out.height()))
        warnings.push_back({Diagnostic::Severity::Warning, name,
                            fmt::format("meta/resolution ({}) disagrees with the channels' size {} x {} "
                                        "(width, height); the channels' size is used",
                                        fmt::join(res->second, ", "), out.width(), out.height()),
                            {}});
    BufferMetadata& md = out.metadata();
    md.camera = cameraOf(meta, out.width(), out.height());
    for (const auto& [key, values] : meta.numbers)
        if (!isLayoutKey(key) && values.size() == 1) md.attributes[key] = fmt::format("{}", values[0]);
    for (const auto& [key, text] : meta.texts)
        if (!isLayoutKey(key)) md.attributes[key] = text;
}

}  // namespace darkroom::h5
