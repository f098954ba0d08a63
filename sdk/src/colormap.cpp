// Colour maps: sampling in the four ParaView colour spaces and the presets.
// Loading ParaView JSON files lives in colormap_json.cpp.
#include "colormap_presets.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/srgb.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>

namespace darkroom {

namespace {

using Vec = std::array<double, 3>;
constexpr double kPi = std::numbers::pi;

// --- colour space conversions (linear RGB <-> XYZ <-> CIELAB <-> Msh) ---
// sRGB primaries, D65 white, the same constants as VTK/ParaView.
constexpr Vec kWhite{0.9505, 1.0, 1.089};

Vec linearToXyz(const Vec& c) {
    return {0.4124 * c[0] + 0.3576 * c[1] + 0.1805 * c[2],
            0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2],
            0.0193 * c[0] + 0.1192 * c[1] + 0.9505 * c[2]};
}

Vec xyzToLinear(const Vec& x) {
    return {3.2406 * x[0] - 1.5372 * x[1] - 0.4986 * x[2],
            -0.9689 * x[0] + 1.8758 * x[1] + 0.0415 * x[2],
            0.0557 * x[0] - 0.2040 * x[1] + 1.0570 * x[2]};
}

double labF(double t) { return t > 0.008856 ? std::cbrt(t) : 7.787 * t + 16.0 / 116.0; }
double labFInverse(double f) {
    const double t = f * f * f;
    return t > 0.008856 ? t : (f - 16.0 / 116.0) / 7.787;
}

Vec linearToLab(const Vec& c) {
    const Vec x = linearToXyz(c);
    const double fx = labF(x[0] / kWhite[0]), fy = labF(x[1] / kWhite[1]), fz = labF(x[2] / kWhite[2]);
    return {116.0 * fy - 16.0, 500.0 * (fx - fy), 200.0 * (fy - fz)};
}

Vec labToLinear(const Vec& lab) {
    const double fy = (lab[0] + 16.0) / 116.0;
    const double fx = fy + lab[1] / 500.0, fz = fy - lab[2] / 200.0;
    return xyzToLinear({labFInverse(fx) * kWhite[0], labFInverse(fy) * kWhite[1], labFInverse(fz) * kWhite[2]});
}

// Msh: magnitude, saturation (angle from the L axis), hue (angle in a-b).
Vec labToMsh(const Vec& lab) {
    const double m = std::sqrt(lab[0] * lab[0] + lab[1] * lab[1] + lab[2] * lab[2]);
    const double s = m > 0.001 ? std::acos(std::clamp(lab[0] / m, -1.0, 1.0)) : 0.0;
    const double h = s > 0.001 ? std::atan2(lab[2], lab[1]) : 0.0;
    return {m, s, h};
}

Vec mshToLab(const Vec& msh) {
    return {msh[0] * std::cos(msh[1]), msh[0] * std::sin(msh[1]) * std::cos(msh[2]),
            msh[0] * std::sin(msh[1]) * std::sin(msh[2])};
}

// Moreland: an unsaturated colour takes a hue that spins away from the
// saturated one, so the path does not cross a hue discontinuity.
double adjustHue(const Vec& saturated, double unsaturatedM) {
    const double m = saturated[0], s = saturated[1], h = saturated[2];
    if (m >= unsaturatedM - 0.1) return h;
    const double spin = s * std::sqrt(unsaturatedM * unsaturatedM - m * m) / (m * std::sin(s));
    return h > -kPi / 3.0 ? h + spin : h - spin;
}

// Moreland, "Diverging Color Maps for Scientific Visualization" (2009), §3.
Vec divergingLerp(const Vec& lin1, const Vec& lin2, double t) {
    Vec a = labToMsh(linearToLab(lin1));
    Vec b = labToMsh(linearToLab(lin2));
    if (a[1] > 0.05 && b[1] > 0.05) {
        double dh = std::abs(a[2] - b[2]);
        if (dh > kPi) dh = 2.0 * kPi - dh;
        if (dh > kPi / 3.0) {
            // Two distinct saturated hues: go through white in the middle.
            const double mid = std::max({a[0], b[0], 88.0});
            if (t < 0.5) {
                b = {mid, 0.0, 0.0};
                t *= 2.0;
            } else {
                a = {mid, 0.0, 0.0};
                t = 2.0 * t - 1.0;
            }
        }
    }
    if (a[1] < 0.05 && b[1] > 0.05)
        a[2] = adjustHue(b, a[0]);
    else if (b[1] < 0.05 && a[1] > 0.05)
        b[2] = adjustHue(a, b[0]);
    const Vec m{a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
    return labToLinear(mshToLab(m));
}

Vec rgbToHsv(const Vec& c) {
    const double mx = std::max({c[0], c[1], c[2]}), mn = std::min({c[0], c[1], c[2]});
    const double d = mx - mn;
    double h = 0.0;
    if (d > 0.0) {
        if (mx == c[0])
            h = (c[1] - c[2]) / d;
        else if (mx == c[1])
            h = 2.0 + (c[2] - c[0]) / d;
        else
            h = 4.0 + (c[0] - c[1]) / d;
        h /= 6.0;
        if (h < 0.0) h += 1.0;
    }
    return {h, mx > 0.0 ? d / mx : 0.0, mx};
}

Vec hsvToRgb(const Vec& hsv) {
    const double h = (hsv[0] - std::floor(hsv[0])) * 6.0, s = hsv[1], v = hsv[2];
    const int i = std::min(int(h), 5);
    const double f = h - i, p = v * (1 - s), q = v * (1 - s * f), u = v * (1 - s * (1 - f));
    switch (i) {
        case 0: return {v, u, p};
        case 1: return {q, v, p};
        case 2: return {p, v, u};
        case 3: return {p, q, v};
        case 4: return {u, p, v};
        default: return {v, p, q};
    }
}

Vec linearOf(const ColorMapPoint& p) { return {p.r, p.g, p.b}; }
Vec encodedOf(const ColorMapPoint& p) {
    return {linearToSrgb(p.r), linearToSrgb(p.g), linearToSrgb(p.b)};
}
Vec decode(const Vec& e) {
    return {srgbToLinear(float(e[0])), srgbToLinear(float(e[1])), srgbToLinear(float(e[2]))};
}
Vec lerp(const Vec& a, const Vec& b, double t) {
    return {a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2])};
}

// Linear colour between two control points at fraction t.
Vec blend(ColorMapSpace space, const ColorMapPoint& p, const ColorMapPoint& q, double t) {
    switch (space) {
        case ColorMapSpace::Lab: return labToLinear(lerp(linearToLab(linearOf(p)), linearToLab(linearOf(q)), t));
        case ColorMapSpace::Diverging: return divergingLerp(linearOf(p), linearOf(q), t);
        case ColorMapSpace::HSV: return decode(hsvToRgb(lerp(rgbToHsv(encodedOf(p)), rgbToHsv(encodedOf(q)), t)));
        case ColorMapSpace::RGB: break;
    }
    return decode(lerp(encodedOf(p), encodedOf(q), t));
}

std::string canonicalName(std::string_view name) {
    std::string s;
    for (char c : name)
        if (c != ' ' && c != '-' && c != '_') s += char(std::tolower(static_cast<unsigned char>(c)));
    const std::string suffix = "(matplotlib)";
    if (s.size() > suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0)
        s.resize(s.size() - suffix.size());
    return s;
}

// ParaView's names for the same maps.
const detail::Preset* findPreset(std::string_view name) {
    std::string key = canonicalName(name);
    if (key == "blackbodyradiation") key = "blackbody";
    if (key == "greyscale" || key == "gray" || key == "grey") key = "grayscale";
    if (key == "bluetoredrainbow") key = "rainbow";
    if (key == "coolwarm") key = "cooltowarm";
    std::size_t n = 0;
    const detail::Preset* all = detail::presets(n);
    for (std::size_t i = 0; i < n; ++i)
        if (canonicalName(all[i].name) == key) return &all[i];
    return nullptr;
}

ColorMapData fromPreset(const detail::Preset& p) {
    ColorMapData m;
    m.name = p.name;
    m.space = p.space;
    for (std::size_t i = 0; i < p.count; ++i)
        m.points.push_back({p.points[i].x, srgbToLinear(p.points[i].r), srgbToLinear(p.points[i].g),
                            srgbToLinear(p.points[i].b)});
    if (p.hasNanColor) {
        m.hasNanColor = true;
        m.nanColor = {srgbToLinear(p.nan[0]), srgbToLinear(p.nan[1]), srgbToLinear(p.nan[2]), 1.0f};
    }
    return m;
}

}  // namespace

namespace detail {
// Defined in colormap_json.cpp.
ColorMapData loadParaViewColorMap(const std::string& path);
}  // namespace detail

const char* toString(ColorMapSpace s) {
    switch (s) {
        case ColorMapSpace::Lab: return "Lab";
        case ColorMapSpace::Diverging: return "Diverging";
        case ColorMapSpace::HSV: return "HSV";
        case ColorMapSpace::RGB: break;
    }
    return "RGB";
}

Color ColorMapData::sample(double t) const {
    if (std::isnan(t)) return nanColor;
    if (points.empty()) return nanColor;
    if (points.size() == 1) return {points[0].r, points[0].g, points[0].b, 1.0f};
    t = std::clamp(t, points.front().x, points.back().x);
    // First segment whose end is at or beyond t (a repeated x is a sharp step:
    // t exactly on it takes the colour of the left segment's end).
    std::size_t i = 1;
    while (i + 1 < points.size() && points[i].x < t) ++i;
    const ColorMapPoint& p = points[i - 1];
    const ColorMapPoint& q = points[i];
    const double span = q.x - p.x;
    const double f = span > 0 ? (t - p.x) / span : 1.0;
    if (f <= 0.0) return {p.r, p.g, p.b, 1.0f};
    if (f >= 1.0) return {q.r, q.g, q.b, 1.0f};
    const Vec c = blend(space, p, q, f);
    return {float(std::max(0.0, c[0])), float(std::max(0.0, c[1])), float(std::max(0.0, c[2])), 1.0f};
}

std::vector<Color> ColorMapData::table(int n) const {
    if (n < 2) throw Error("a colour map table needs at least two entries");
    std::vector<Color> out(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) out[std::size_t(i)] = sample(i == n - 1 ? 1.0 : double(i) / double(n - 1));
    return out;
}

std::vector<std::string> colorMapPresets() {
    std::size_t n = 0;
    const detail::Preset* all = detail::presets(n);
    std::vector<std::string> names;
    for (std::size_t i = 0; i < n; ++i) names.emplace_back(all[i].name);
    return names;
}

bool isColorMapPreset(std::string_view name) { return findPreset(name) != nullptr; }

ColorMapData loadColorMap(std::string_view spec) {
    if (const detail::Preset* p = findPreset(spec)) return fromPreset(*p);
    if (spec.empty()) {
        std::string names;
        for (const auto& n : colorMapPresets()) names += (names.empty() ? "" : ", ") + n;
        throw Error("no colour map given; name a preset (" + names + ") or a ParaView colour-map JSON file");
    }
    return detail::loadParaViewColorMap(std::string(spec));
}

}  // namespace darkroom
