// The family table, knob checking and naming, and the corner's closed-form AO.
#include <darkroom/error.h>
#include <darkroom/accuracy/stress_scenes.h>

#include "stress_families.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace darkroom::stress {

namespace {

struct Family {
    const char* name;
    const char* knob;  // empty: no knob
    const char* tag;   // prefix of the knob value in the scene name
    double lo, hi;     // accepted knob range
    std::vector<double> values;
    detail::Builder build;
};

const std::vector<Family>& table() {
    static const std::vector<Family> t = {
        {"plane", "", "", 0, 0, {0}, detail::buildPlane},
        {"corner", "", "", 0, 0, {0}, detail::buildCorner},
        {"terrain", "", "", 0, 0, {0}, detail::buildTerrain},
        {"particles", "projected radius (px)", "r", 0.25, 64, {0.5, 1, 2, 4, 8, 20}, detail::buildParticles},
        {"streamlines", "line width (px)", "w", 0.1, 16, {0.25, 0.5, 1, 2, 4}, detail::buildStreamlines},
        {"slabs", "gap / AO radius", "g", 0.01, 10, {0.05, 0.1, 0.25, 0.5, 1, 2}, detail::buildSlabs},
        {"staircase", "step height / AO radius", "h", 0.1, 10, {0.25, 0.5, 1, 2, 4}, detail::buildStaircase},
        {"grazing", "view angle (deg)", "", 0, 89.5, {80, 82, 84, 86, 88, 89}, detail::buildGrazing},
        {"border", "", "", 0, 0, {0}, detail::buildBorder},
        {"gyroid", "", "", 0, 0, {0}, detail::buildGyroid},
        {"stripes", "stripe period (px)", "p", 1, 64, {1.5, 2, 3, 4, 8}, detail::buildStripes},
        {"shells", "nested shells", "n", 1, 8, {1, 2, 3, 4}, detail::buildShells},
        {"sheets", "sheets in the stack", "n", 1, 32, {2, 4, 8, 16}, detail::buildSheets},
    };
    return t;
}

std::string knownFamilies() {
    std::string s;
    for (const auto& f : table()) s += (s.empty() ? "" : ", ") + std::string(f.name);
    return s;
}

const Family& find(const std::string& family) {
    for (const auto& f : table())
        if (family == f.name) return f;
    throw Error("unknown stress scene family '" + family + "'; expected one of: " + knownFamilies());
}

// Shortest round-trip-ish text of a knob value: 0.5, 1, 89.5 (no exponent
// in the accepted ranges, so file-name safe).
std::string number(double v) {
    std::ostringstream os;
    os.precision(6);
    os << v;
    return os.str();
}

// Widens [fieldMin, fieldMax] to every value of the colour field, and checks
// the invariants every family promises (the field on every object, no NaN).
void finish(StressScene& s) {
    for (const auto& o : s.scene->objects) {
        const ScalarField* f = o.field(s.colorField);
        if (!f) throw std::logic_error("stress scene " + s.name + ": object '" + o.name + "' lacks its colour field");
        for (float v : f->values) {
            if (std::isnan(v)) throw std::logic_error("stress scene " + s.name + ": NaN in '" + o.name + "'");
            s.fieldMin = std::min(s.fieldMin, double(v));
            s.fieldMax = std::max(s.fieldMax, double(v));
        }
    }
}

}  // namespace

std::vector<std::string> families() {
    std::vector<std::string> v;
    for (const auto& f : table()) v.emplace_back(f.name);
    return v;
}

std::vector<double> knobValues(const std::string& family) { return find(family).values; }

StressScene make(const std::string& family, double knobValue, const Options& options) {
    const Family& f = find(family);
    if (options.width < 1 || options.height < 1 || options.width > 65536 || options.height > 65536)
        throw Error("stress scene '" + family + "': image size " + std::to_string(options.width) + " x " +
                    std::to_string(options.height) + " is invalid; expected 1 .. 65536 pixels each way");
    const bool hasKnob = *f.knob != '\0';
    if (!hasKnob && knobValue != 0.0)
        throw Error("stress scene '" + family + "' has no knob; expected knob value 0, got " + number(knobValue));
    if (hasKnob && !(knobValue >= f.lo && knobValue <= f.hi))
        throw Error("stress scene '" + family + "': " + f.knob + " must be in [" + number(f.lo) + ", " +
                    number(f.hi) + "], got " + number(knobValue));
    StressScene s;
    s.family = f.name;
    s.knob = f.knob;
    s.knobValue = hasKnob ? knobValue : 0.0;
    s.name = hasKnob ? family + "-" + f.tag + number(knobValue) : family;
    f.build(s, s.knobValue, options);
    finish(s);
    return s;
}

std::vector<StressScene> sweep(const std::string& family, const Options& options) {
    std::vector<StressScene> v;
    for (double k : knobValues(family)) v.push_back(make(family, k, options));
    return v;
}

double cornerAo(double distance, double radius, reference::AoWeighting weighting) {
    if (!(radius > 0)) throw Error("cornerAo: radius must be > 0, got " + number(radius));
    const double k = std::min(std::abs(distance) / radius, 1.0);
    if (weighting == reference::AoWeighting::Uniform) return 0.5 * (1.0 + k);
    constexpr double pi = 3.14159265358979323846;
    return 1.0 - (std::acos(k) - k * std::sqrt(1.0 - k * k)) / pi;
}

}  // namespace darkroom::stress
