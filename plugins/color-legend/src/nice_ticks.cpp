#include "nice_ticks.h"

#include <darkroom/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace darkroom::legend {

namespace {

// ⁰ ¹ ² ³ ⁴ ⁵ ⁶ ⁷ ⁸ ⁹ in UTF-8.
const char* const kSuperDigits[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                      "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};

// Decimal exponent of a positive number, robust to 10^k coming out as 9.999...
int decade(double x) { return int(std::floor(std::log10(x) + 1e-9)); }

// Typeset minus (U+2212) rather than a hyphen, as TeX and matplotlib write it.
const char* const kMinus = "\u2212";

std::string fixed(double v, int decimals) {
    std::string s = fmt::format("{:.{}f}", v, std::max(0, decimals));
    if (s.find_first_not_of("-0.") == std::string::npos) s = decimals > 0 ? fmt::format("{:.{}f}", 0.0, decimals) : "0";
    if (s[0] == '-') s = kMinus + s.substr(1);
    return s;
}

double position(double v, double minimum, double maximum) {
    return maximum == minimum ? 0.5 : (v - minimum) / (maximum - minimum);
}

}  // namespace

double niceNumber(double x, bool round) {
    const int e = decade(x);
    const double p = std::pow(10.0, e);
    const double f = x / p;
    double n;
    if (round) n = f < 1.5 ? 1 : f < 3 ? 2 : f < 7 ? 5 : 10;
    else n = f <= 1 ? 1 : f <= 2 ? 2 : f <= 5 ? 5 : 10;
    return n * p;
}

std::string superscript(int exponent) {
    std::string s = exponent < 0 ? "\u207b" : "";  // superscript minus
    const std::string digits = std::to_string(std::abs(exponent));
    for (char c : digits) s += kSuperDigits[c - '0'];
    return s;
}

std::string formatTickLabel(double value, double step, bool scientific) {
    const int stepDecade = decade(step > 0 ? step : (value != 0 ? std::fabs(value) : 1.0));
    if (!scientific) return fixed(value, -stepDecade);
    if (value == 0) return "0";
    int e = decade(std::fabs(value));
    double mantissa = value / std::pow(10.0, e);
    int decimals = std::max(0, e - stepDecade);
    // Rounding may carry the mantissa to 10 (9.99 -> 10.0).
    if (std::fabs(std::stod(fixed(mantissa, decimals))) >= 10) {
        ++e;
        mantissa /= 10;
        decimals = std::max(0, decimals - 1);
    }
    const std::string m = fixed(mantissa, decimals);
    const std::string minusOne = std::string(kMinus) + "1";
    return (m == "1" ? "" : m == minusOne ? std::string(kMinus) : m + "\u00d7") + "10" + superscript(e);
}

std::vector<Tick> linearTicks(double minimum, double maximum, int count) {
    std::vector<Tick> ticks;
    if (!std::isfinite(minimum) || !std::isfinite(maximum)) return ticks;
    const double lo = std::min(minimum, maximum), hi = std::max(minimum, maximum);
    if (hi == lo) {
        const double step = lo != 0 ? std::pow(10.0, decade(std::fabs(lo)) - 2) : 1.0;
        ticks.push_back({lo, 0.5, formatTickLabel(lo, step, std::fabs(lo) >= 1e5 || std::fabs(lo) < 1e-3)});
        if (lo == 0) ticks.back().label = "0";
        return ticks;
    }
    count = std::max(2, count);
    // Heckbert's step, then its nice neighbours (…, 0.1, 0.2, 0.5, 1, 2, …): the
    // one whose ticks inside the range come nearest `count` wins (the larger on
    // a tie). Heckbert's loose labelling widens the axis to the ticks; a legend
    // cannot, so a step that leaves two ticks inside is often too coarse.
    const double heckbert = niceNumber(niceNumber(hi - lo, false) / (count - 1), true);
    auto inside = [&](double s) {
        const double e = s * 1e-9;
        return (long long)std::floor((hi + e) / s) - (long long)std::ceil((lo - e) / s) + 1;
    };
    double step = heckbert;
    long long bestMiss = std::llabs(inside(heckbert) - count);
    const int e = decade(heckbert);
    for (int k = e - 1; k <= e + 1; ++k)
        for (const double m : {1.0, 2.0, 5.0}) {
            const double candidate = m * std::pow(10.0, k);
            const long long miss = std::llabs(inside(candidate) - count);
            if (miss < bestMiss || (miss == bestMiss && candidate > step)) {
                bestMiss = miss;
                step = candidate;
            }
        }
    const double eps = step * 1e-9;
    const long long first = (long long)std::ceil((lo - eps) / step);
    const long long last = (long long)std::floor((hi + eps) / step);
    const bool scientific = std::max(std::fabs(double(first) * step), std::fabs(double(last) * step)) >= 1e5 ||
                            step < 1e-3;
    for (long long k = first; k <= last; ++k) {
        double v = double(k) * step;
        if (std::fabs(v) < eps) v = 0;  // no "-0"
        ticks.push_back({v, position(v, minimum, maximum), formatTickLabel(v, step, scientific)});
    }
    return ticks;
}

std::vector<Tick> logTicks(double minimum, double maximum, int count) {
    if (!(minimum > 0) || !(maximum > 0) || !std::isfinite(minimum) || !std::isfinite(maximum))
        throw Error(fmt::format("a log-scale legend needs a positive range; got {} to {}", minimum, maximum));
    const double lo = std::min(minimum, maximum), hi = std::max(minimum, maximum);
    const double llo = std::log10(minimum), lhi = std::log10(maximum);
    auto at = [&](double v, std::string label) {
        return Tick{v, llo == lhi ? 0.5 : (std::log10(v) - llo) / (lhi - llo), std::move(label)};
    };
    auto label = [](double v) {
        const int e = decade(v);
        const double m = v / std::pow(10.0, e);
        const long long mi = std::llround(m);
        if (e >= -3 && e <= 4) return fixed(v, std::max(0, -e));
        return (mi == 1 ? std::string() : std::to_string(mi) + "\u00d7") + "10" + superscript(e);
    };
    count = std::max(2, count);
    std::vector<Tick> ticks;
    const int d0 = int(std::ceil(std::log10(lo) - 1e-9)), d1 = int(std::floor(std::log10(hi) + 1e-9));
    // Decades when there are enough of them to read the scale by; fewer than
    // three leave too few labels, so 1-2-5 steps instead.
    if (d1 - d0 + 1 >= 3) {
        const int every = std::max(1, int(std::ceil(double(d1 - d0 + 1) / double(count))));
        for (int e = d0; e <= d1; ++e)
            if ((e - d0) % every == 0) ticks.push_back(at(std::pow(10.0, e), label(std::pow(10.0, e))));
        return ticks;
    }
    for (int e = d0 - 1; e <= d1; ++e)
        for (double m : {1.0, 2.0, 5.0}) {
            const double v = m * std::pow(10.0, e);
            if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) ticks.push_back(at(v, label(v)));
        }
    if (ticks.size() >= 2) return ticks;
    // Less than a factor of 2.5 wide: round numbers on a linear step, placed in log.
    ticks.clear();
    for (const Tick& l : linearTicks(lo, hi, count))
        if (l.value > 0) ticks.push_back({l.value, at(l.value, "").t, l.label});
    return ticks;
}

}  // namespace darkroom::legend
