// TTK .vti images: VTK XML ImageData decoded with the scene reader's DataArray
// code (framework/data/include/darkroom/data/formats/vtk_data_array.h), TTK's camera from field data.
#include <darkroom/data/formats/text_cursor.h>
#include <darkroom/data/formats/vtk_data_array.h>

#include <darkroom/error.h>
#include <darkroom/data/formats/vti.h>
#include "ttk_depth.h"
#include <darkroom/limits.h>

#include <fmt/format.h>

#include <array>
#include <cctype>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <sstream>

namespace darkroom {

namespace {

constexpr double kPi = std::numbers::pi;

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

[[noreturn]] void fail(const std::string& path, const mesh::XmlElement& e, const std::string& what) {
    throw Error(fmt::format("{}:{}: {}", path, e.line, what));
}

// "x0 x1 y0 y1 z0 z1"
std::array<long long, 6> extent(const std::string& path, const mesh::XmlElement& e, const char* key) {
    const std::string* v = e.attribute(key);
    if (!v) fail(path, e, fmt::format("<{}> lacks {}; expected six integers 'x0 x1 y0 y1 z0 z1'", e.name, key));
    std::istringstream in(*v);
    std::array<long long, 6> x{};
    for (auto& k : x)
        if (!(in >> k)) fail(path, e, fmt::format("{} is '{}'; expected six integers 'x0 x1 y0 y1 z0 z1'", key, *v));
    return x;
}

}  // namespace

Camera toDarkroomCamera(const TtkCamera& t) {
    Camera c;
    c.position = t.position;
    c.forward = normalize(t.direction);
    c.up = t.up;
    c.width = t.width;
    c.height = t.height;
    if (t.orthographic) {
        c.projection = Camera::Projection::Orthographic;
        c.viewHeight = t.viewHeight;
    } else {
        c.projection = Camera::Projection::Perspective;
        const double aspect = t.width > 0 && t.height > 0 ? double(t.height) / double(t.width) : 1.0;
        const double halfHeight = 0.5 * (t.angle * kPi / 180.0) * aspect;
        c.fovYDegrees = 2.0 * std::atan(halfHeight) * 180.0 / kPi;
    }
    return c;
}

float ttkDepthToPlanar(float d, double nearPlane, double farPlane) {
    return formats::planarFromTtkDepth(d, nearPlane, farPlane);
}

namespace {

// TTK's camera, from the image's field data (none when it has no CamPosition).
std::optional<TtkCamera> ttkCameraOf(const std::string& path, const mesh::XmlElement* image,
                                     const mesh::VtkXmlEncoding& enc, long long W, long long H) {
    // Field data: TTK's camera.
    std::map<std::string, std::vector<double>> field;
    if (const mesh::XmlElement* fd = image->child("FieldData"))
        for (const auto& c : fd->children)
            if (c->name == "DataArray") {
                auto a = mesh::readVtkDataArray(*c, enc);
                field[a.name] = std::move(a.values);
            }
    const auto vec = [&](const char* name, std::size_t n) -> const std::vector<double>* {
        auto it = field.find(name);
        return it != field.end() && it->second.size() >= n ? &it->second : nullptr;
    };
    if (const auto* pos = vec("CamPosition", 3)) {
        TtkCamera t;
        t.position = {(*pos)[0], (*pos)[1], (*pos)[2]};
        if (const auto* dir = vec("CamDirection", 3)) t.direction = {(*dir)[0], (*dir)[1], (*dir)[2]};
        else if (const auto* f = vec("CamFocalPoint", 3)) t.direction = Vec3{(*f)[0], (*f)[1], (*f)[2]} - t.position;
        if (const auto* up = vec("CamUp", 3)) t.up = {(*up)[0], (*up)[1], (*up)[2]};
        if (const auto* h = vec("CamHeight", 1)) t.viewHeight = (*h)[0];
        if (const auto* a = vec("CamAngle", 1)) t.angle = (*a)[0];
        if (const auto* m = vec("ProjectionMode", 1)) t.orthographic = (*m)[0] == 0;
        if (const auto* nf = vec("CamNearFar", 2)) {
            t.nearPlane = (*nf)[0];
            t.farPlane = (*nf)[1];
        }
        t.width = int(W);
        t.height = int(H);
        if (!(length(t.direction) > 0) || !(length(cross(t.direction, t.up)) > 0))
            throw Error(fmt::format("{}: CamDirection (or CamFocalPoint - CamPosition) is zero or parallel to CamUp; "
                                    "expected a usable TTK camera",
                                    path));
        return t;
    }

    return std::nullopt;
}

// The point arrays as channels (a 1-component Depth array as Z), rows
// flipped: VTK images start at the bottom.
void readChannels(const std::string& path, const mesh::XmlElement* piece, const mesh::VtkXmlEncoding& enc,
                  long long W, long long H, VtiImage& out) {
    std::vector<mesh::VtkArray> arrays;
    if (const mesh::XmlElement* pd = piece->child("PointData"))
        for (const auto& c : pd->children)
            if (c->name == "DataArray") {
                arrays.push_back(mesh::readVtkDataArray(*c, enc, std::size_t(W * H)));
                const auto& a = arrays.back();
                if (a.values.size() != std::size_t(W * H) * std::size_t(a.components))
                    fail(path, *c, fmt::format("DataArray '{}' has {} values; expected {} x {} pixels x {} components",
                                               a.name, a.values.size(), W, H, a.components));
            }
    if (arrays.empty()) throw Error(fmt::format("{}: the image has no point arrays; nothing to read", path));
    std::vector<ChannelDesc> channels;
    for (const auto& a : arrays) {
        const bool depth = lower(a.name) == "depth" && a.components == 1;
        for (int k = 0; k < a.components; ++k)
            channels.push_back({depth ? std::string("Z") : a.components == 1 ? a.name : fmt::format("{}.{}", a.name, k),
                                ChannelType::Float32});
    }
    out.buffer = makeCpuBuffer(int(W), int(H), channels);
    std::size_t ch = 0;
    for (const auto& a : arrays) {
        const bool depth = channels[ch].name == "Z" && lower(a.name) == "depth";
        double nearPlane = 0, farPlane = 0;
        if (depth && out.ttkCamera) {
            nearPlane = out.ttkCamera->nearPlane;
            farPlane = out.ttkCamera->farPlane;
        }
        if (depth && !out.ttkCamera) {
            bool within01 = true;
            for (double v : a.values) within01 &= std::isnan(v) || (v >= 0 && v <= 1);
            if (within01)
                out.warnings.push_back({Diagnostic::Severity::Warning, path,
                                        "Depth lies in [0,1] but the file has no TTK camera (CamNearFar): Z keeps "
                                        "the values as they are (1.0 kept, not turned into +inf; NaN -> +inf)",
                                        {}});
        }
        for (int k = 0; k < a.components; ++k, ++ch) {
            float* dst = out.buffer->writeFloat(channels[ch].name);
            for (long long y = 0; y < H; ++y)
                for (long long x = 0; x < W; ++x) {
                    const float v = float(a.values[std::size_t((H - 1 - y) * W + x) * a.components + std::size_t(k)]);
                    dst[y * W + x] = depth ? ttkDepthToPlanar(v, nearPlane, farPlane) : v;
                }
        }
    }
}

}  // namespace

VtiImage readVti(const std::string& path) {
    const std::string data = mesh::readWholeFile(path, "image");
    const mesh::VtkXmlDocument doc = mesh::parseVtkXml(data, path);
    const mesh::XmlElement& root = *doc.root;
    if (root.name != "VTKFile") fail(path, root, "expected <VTKFile> as the root element, got <" + root.name + ">");
    if (root.attributeOr("type", "") != "ImageData")
        fail(path, root, "dataset type is '" + root.attributeOr("type", "") + "'; expected ImageData");
    const mesh::VtkXmlEncoding enc = mesh::vtkXmlEncoding(doc, path);
    const mesh::XmlElement* image = root.child("ImageData");
    if (!image) fail(path, root, "missing <ImageData>");
    const auto whole = extent(path, *image, "WholeExtent");
    // Sizes in checked 64-bit arithmetic: extents near the integer limits would overflow.
    long long W = 0, H = 0;
    const bool overflow = __builtin_sub_overflow(whole[1], whole[0], &W) || __builtin_add_overflow(W, 1, &W) ||
                          __builtin_sub_overflow(whole[3], whole[2], &H) || __builtin_add_overflow(H, 1, &H);
    if (overflow || W < 1 || H < 1 || W > (1 << 20) || H > (1 << 20) || whole[5] != whole[4])
        throw InputError(fmt::format("{}:{}: WholeExtent {} {} {} {} {} {} is not a 2-D image (expected x0 <= x1 and "
                                     "y0 <= y1 at most 1048576 apart, and one z slice)",
                                     path, image->line, whole[0], whole[1], whole[2], whole[3], whole[4], whole[5]));
    checkImagePixels(std::uint64_t(W), std::uint64_t(H), fmt::format("{}:{}: WholeExtent", path, image->line));
    const mesh::XmlElement* piece = image->child("Piece");
    if (!piece) fail(path, *image, "missing <Piece>");
    if (extent(path, *piece, "Extent") != whole)
        fail(path, *piece, "the piece's Extent differs from WholeExtent; images split into pieces are not read");
    for (const auto& c : image->children)
        if (c->name == "Piece" && c.get() != piece) fail(path, *c, "a second <Piece>; one piece per image is read");

    VtiImage out;
    out.ttkCamera = ttkCameraOf(path, image, enc, W, H);
    readChannels(path, piece, enc, W, H, out);
    if (out.ttkCamera) out.buffer->metadata().camera = toDarkroomCamera(*out.ttkCamera);
    out.buffer->metadata().attributes["source"] = path;
    return out;
}

}  // namespace darkroom
