// ParaView colour-map JSON ("Save as preset" / ColorMaps.json / TTK Cinema
// databases): RGBPoints are sRGB-encoded and x is in data units.
#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/input_file.h>
#include <darkroom/srgb.h>
#include <darkroom/strings.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

namespace darkroom::detail {

namespace {

using Json = nlohmann::json;

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    throw Error("colour map '" + path + "': " + why);
}

double number(const std::string& path, const Json& v, const std::string& where) {
    if (!v.is_number()) fail(path, where + " must be a number, got " + v.dump());
    return v.get<double>();
}

ColorMapSpace parseSpace(const std::string& path, const std::string& s) {
    std::string k;
    for (char c : s) k += char(std::tolower(static_cast<unsigned char>(c)));
    if (k == "rgb") return ColorMapSpace::RGB;
    // CIEDE2000 interpolation differs from plain Lab only in how it spaces the
    // colours along the same path; plain Lab is a close, documented stand-in.
    if (k == "lab" || k == "lab/ciede2000" || k == "cielab") return ColorMapSpace::Lab;
    if (k == "diverging" || k == "msh") return ColorMapSpace::Diverging;
    if (k == "hsv") return ColorMapSpace::HSV;
    fail(path, "ColorSpace '" + s + "' is not supported (expected RGB, Lab, Diverging or HSV)");
}

ColorMapData parseEntry(const std::string& path, const Json& e) {
    ColorMapData m;
    m.name = e.contains("Name") && e["Name"].is_string() ? e["Name"].get<std::string>()
                                                          : std::filesystem::path(path).stem().string();
    const Json& pts = e["RGBPoints"];
    if (!pts.is_array()) fail(path, "RGBPoints must be an array of numbers x, r, g, b, ...");
    if (pts.size() % 4 != 0 || pts.size() < 4)
        fail(path, "RGBPoints must hold x, r, g, b quadruples; got " + std::to_string(pts.size()) +
                       " numbers");
    for (std::size_t i = 0; i < pts.size(); i += 4) {
        const std::string where = "RGBPoints[" + std::to_string(i / 4) + "]";
        ColorMapPoint p;
        p.x = number(path, pts[i], where + ".x");
        const double r = number(path, pts[i + 1], where + ".r");
        const double g = number(path, pts[i + 2], where + ".g");
        const double b = number(path, pts[i + 3], where + ".b");
        if (!std::isfinite(p.x) || !std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b))
            fail(path, where + " is not finite");
        p.r = srgbToLinear(float(r));
        p.g = srgbToLinear(float(g));
        p.b = srgbToLinear(float(b));
        if (!m.points.empty() && p.x < m.points.back().x)
            fail(path, where + ".x = " + std::to_string(p.x) + " is smaller than the previous point's x; "
                       "RGBPoints must be sorted by x");
        m.points.push_back(p);
    }
    // A single point is a constant map.
    if (m.points.size() == 1) m.points.push_back(m.points.front());
    const double x0 = m.points.front().x, x1 = m.points.back().x;
    for (auto& p : m.points) p.x = x1 > x0 ? (p.x - x0) / (x1 - x0) : (&p == &m.points.front() ? 0.0 : 1.0);
    m.points.back().x = 1.0;

    if (e.contains("ColorSpace")) {
        if (!e["ColorSpace"].is_string()) fail(path, "ColorSpace must be a string");
        m.space = parseSpace(path, e["ColorSpace"].get<std::string>());
    }
    if (e.contains("NanColor")) {
        const Json& n = e["NanColor"];
        if (!n.is_array() || (n.size() != 3 && n.size() != 4))
            fail(path, "NanColor must be [r, g, b] or [r, g, b, a]");
        float c[4] = {0, 0, 0, 1};
        for (std::size_t i = 0; i < n.size(); ++i) c[i] = float(number(path, n[i], "NanColor"));
        if (e.contains("NanOpacity")) c[3] = float(number(path, e["NanOpacity"], "NanOpacity"));
        m.nanColor = {srgbToLinear(c[0]), srgbToLinear(c[1]), srgbToLinear(c[2]), c[3]};
        m.hasNanColor = true;
    }
    return m;
}

}  // namespace

ColorMapData loadParaViewColorMap(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) {
        // The spec arrives resolved against the pipeline's folder: its last
        // part is what was typed when it was meant as a preset.
        // (Split by hand: path::filename() would be one more symbol the SDK exports.)
        std::string typed = path.substr(path.find_last_of('/') + 1);
        for (char& c : typed) c = char(std::tolower(static_cast<unsigned char>(c)));
        // A missing input file is bad input (exit 2, docs/cli.md), as every reader's.
        throw InputError("colour map '" + path + "': no such file, and not a preset name" +
                         didYouMean(typed, colorMapPresets()) + " (" + join(colorMapPresets(), ", ") + ")");
    }
    // A FIFO, a device or a directory is refused (InputError), not read without end.
    const std::string text = readInputFile(path, "colour map");
    Json doc;
    try {
        doc = Json::parse(text);
    } catch (const Json::exception& e) {
        // nlohmann's message carries the line and column.
        fail(path, std::string("not valid JSON: ") + e.what());
    }
    try {
        if (doc.is_object()) {
            if (!doc.contains("RGBPoints")) fail(path, "the object has no RGBPoints");
            return parseEntry(path, doc);
        }
        if (!doc.is_array()) fail(path, "expected an array of colour-map objects or one such object");
        for (const Json& e : doc)
            if (e.is_object() && e.contains("RGBPoints")) return parseEntry(path, e);
        fail(path, "no entry has RGBPoints (indexed/categorical colour maps are not supported)");
    } catch (const Json::exception& e) {
        fail(path, std::string("unexpected structure: ") + e.what());
    }
}

}  // namespace darkroom::detail
