// Writing TTK-style .vti images (for tests and for handing images to TTK).
#include <darkroom/atomic_file.h>
#include <darkroom/error.h>
#include <darkroom/data/formats/vti.h>

#include <fmt/format.h>
#include <zlib.h>

#include <cmath>
#include <cstdint>
#include <algorithm>
#include <cstring>
#include <limits>

namespace darkroom {

namespace {

std::string base64(std::string_view in) {
    static const char* abc = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    std::size_t i = 0;
    for (; i + 2 < in.size(); i += 3) {
        const unsigned v = (unsigned(std::uint8_t(in[i])) << 16) | (unsigned(std::uint8_t(in[i + 1])) << 8) |
                           std::uint8_t(in[i + 2]);
        for (int k = 3; k >= 0; --k) out += abc[(v >> (6 * k)) & 63];
    }
    if (i < in.size()) {
        unsigned v = unsigned(std::uint8_t(in[i])) << 16;
        if (i + 1 < in.size()) v |= unsigned(std::uint8_t(in[i + 1])) << 8;
        out += abc[(v >> 18) & 63];
        out += abc[(v >> 12) & 63];
        out += i + 1 < in.size() ? abc[(v >> 6) & 63] : '=';
        out += '=';
    }
    return out;
}

template <class T>
void put(std::string& out, T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));  // little-endian hosts only, as the header says
    out.append(b, sizeof(T));
}

// One appended block: UInt32 header + data, or the zlib block table + data.
std::string block(const std::string& raw, bool zlib) {
    std::string out;
    if (!zlib) {
        put(out, std::uint32_t(raw.size()));
        return out + raw;
    }
    uLongf n = compressBound(uLong(raw.size()));
    std::string comp(n, '\0');
    if (compress(reinterpret_cast<Bytef*>(comp.data()), &n, reinterpret_cast<const Bytef*>(raw.data()),
                 uLong(raw.size())) != Z_OK)
        throw Error("zlib compression failed");
    comp.resize(n);
    put(out, std::uint32_t(1));
    put(out, std::uint32_t(raw.size()));
    put(out, std::uint32_t(raw.size()));
    put(out, std::uint32_t(comp.size()));
    return out + comp;
}

}  // namespace

void writeVti(const std::string& path, const Buffer& image, const std::optional<TtkCamera>& camera,
              const VtiWriteOptions& options) {
    const int W = image.width(), H = image.height();
    std::string appended, fieldXml, pointXml;
    const auto addArray = [&](std::string& xml, const std::string& name, const char* type, int components,
                              const std::string& raw) {
        xml += fmt::format("        <DataArray type=\"{}\" Name=\"{}\" NumberOfComponents=\"{}\" format=\"appended\" "
                           "offset=\"{}\"/>\n",
                           type, name, components, appended.size());
        const std::string b = block(raw, options.zlib);
        appended += options.base64 ? base64(b) : b;
    };
    const auto doubles = [&](const std::string& name, std::initializer_list<double> v) {
        std::string raw;
        for (double x : v) put(raw, x);
        addArray(fieldXml, name, "Float64", int(v.size()), raw);
    };
    if (camera) {
        const TtkCamera& c = *camera;
        doubles("CamPosition", {c.position.x, c.position.y, c.position.z});
        doubles("CamDirection", {c.direction.x, c.direction.y, c.direction.z});
        doubles("CamUp", {c.up.x, c.up.y, c.up.z});
        doubles("CamHeight", {c.viewHeight});
        doubles("CamAngle", {c.angle});
        doubles("ProjectionMode", {c.orthographic ? 0.0 : 1.0});
        doubles("CamNearFar", {c.nearPlane, c.farPlane});
        doubles("Resolution", {double(W), double(H)});
    }
    const bool normalise = camera && camera->farPlane > camera->nearPlane;
    for (const auto& ch : image.channels()) {
        const float* src = image.hostFloat(ch.name);
        if (!src) continue;  // uint32 ids are not part of TTK's float images
        std::string raw;
        raw.reserve(std::size_t(W) * H * 4);
        const bool depth = ch.name == "Z";
        for (int y = H - 1; y >= 0; --y)  // VTK rows run bottom to top
            for (int x = 0; x < W; ++x) {
                float v = src[std::size_t(y) * W + x];
                if (depth) {
                    if (normalise)
                        v = std::isinf(v) ? 1.f
                                          : float(std::clamp((v - camera->nearPlane) /
                                                                 (camera->farPlane - camera->nearPlane),
                                                             0.0, 1.0));
                    else if (std::isinf(v))
                        v = std::numeric_limits<float>::quiet_NaN();
                }
                put(raw, v);
            }
        addArray(pointXml, depth ? "Depth" : ch.name, "Float32", 1, raw);
    }
    std::string xml = fmt::format(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"ImageData\" version=\"1.0\" byte_order=\"LittleEndian\" "
        "header_type=\"UInt32\"{}>\n"
        "  <ImageData WholeExtent=\"0 {} 0 {} 0 0\" Origin=\"0 0 0\" Spacing=\"1 1 1\">\n"
        "    <FieldData>\n{}    </FieldData>\n"
        "    <Piece Extent=\"0 {} 0 {} 0 0\">\n      <PointData>\n{}      </PointData>\n    </Piece>\n"
        "  </ImageData>\n  <AppendedData encoding=\"{}\">\n   _",
        options.zlib ? " compressor=\"vtkZLibDataCompressor\"" : "", W - 1, H - 1, fieldXml, W - 1, H - 1,
        pointXml, options.base64 ? "base64" : "raw");
    xml += appended;
    xml += "\n  </AppendedData>\n</VTKFile>\n";
    writeFileAtomic(path, xml);
}

}  // namespace darkroom
