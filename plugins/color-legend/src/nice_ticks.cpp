#include "nice_ticks.h"

#include <darkroom/error.h>

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>

namespace darkroom::legend {

namespace {

// ⁰ ¹ ² ³ ⁴ ⁵ ⁶ ⁷ ⁸ ⁹ in UTF-8.
const char* const kSuperDigits[10] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                      "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};

// Decimal exponent of a positive, finite number, robust to 10^k coming out as 9.999...
int decade(double x) { return int(std::floor(std::log10(x) + 1e-9)); }

// x / 10^e for the exponents of every finite double: 10^e underflows to zero
// below 10^-323, so the smallest ones are divided in two steps.
double scaleByDecade(double x, int e) {
    return e < -300 ? (x * 1e300) / std::pow(10.0, e + 300) : x / std::pow(10.0, e);
}

// Typeset minus (U+2212) rather than a hyphen, as TeX and matplotlib write it.
const char* const kMinus = "\u2212";

// The decimal digits of |x| with `decimals` decimals: ASCII, no sign. Labels
// are built from these and the sign of the number, never parsed back.
std::string digits(double x, int decimals) { return fmt::format("{:.{}f}", std::fabs(x), std::clamp(decimals, 0, 40)); }

// |x| in fmt's scientific notation with `decimals` decimals: the mantissa's
// digits and the exponent fmt chose after rounding (9.996e-4 to two decimals
// is 1.00e-03). The exponent is read from fmt's ASCII output, never from a label.
struct Scientific {
    std::string mantissa;
    int exponent = 0;
};
Scientific scientificDigits(double x, int decimals) {
    const std::string s = fmt::format("{:.{}e}", std::fabs(x), std::clamp(decimals, 0, 16));
    const std::size_t e = s.find('e');
    const char* p = s.data() + e + 1;
    if (*p == '+') ++p;
    Scientific out{s.substr(0, e)};
    std::from_chars(p, s.data() + s.size(), out.exponent);
    return out;
}

std::string fixed(double v, int decimals) {
    const std::string s = digits(v, decimals);
    const bool zero = s.find_first_not_of("0.") == std::string::npos;  // no "-0.0"
    return (v < 0 && !zero ? kMinus : "") + s;
}

// (v - minimum) / (maximum - minimum); in halves where the difference
// overflows (halves of normal numbers are exact).
double position(double v, double minimum, double maximum) {
    if (maximum == minimum) return 0.5;
    if (std::isfinite(maximum - minimum)) return (v - minimum) / (maximum - minimum);
    return (v / 2 - minimum / 2) / (maximum / 2 - minimum / 2);
}

// The first and last multiples k of step s in [lo, hi], ends included within
// 1e-9 s (as quotients, which cannot overflow where lo - 1e-9 s can).
struct Multiples {
    double first, last;
};
Multiples multiplesInside(double lo, double hi, double s) {
    return {std::ceil(lo / s - 1e-9), std::floor(hi / s + 1e-9)};
}

// How many multiples of step s lie in [lo, hi], or -1 when s is no usable
// step: zero, infinite, or so small next to the values that k s for
// neighbouring k would not be distinct doubles (k past 2^52).
long long insideCount(double lo, double hi, double s) {
    if (!(s > 0) || !std::isfinite(s)) return -1;
    const Multiples k = multiplesInside(lo, hi, s);
    if (!(std::fabs(k.first) < 0x1p52 && std::fabs(k.last) < 0x1p52)) return -1;
    return (long long)k.last - (long long)k.first + 1;
}

// Heckbert's step for [lo, hi] (hi > lo), or infinity where it is not a
// finite positive number (a span past the largest double, or below the
// smallest normal one).
double heckbertStep(double lo, double hi, int count) {
    const double span = hi - lo;
    if (!std::isfinite(span) || span < 1e-300) return std::numeric_limits<double>::infinity();
    const double loose = niceNumber(span, false) / (count - 1);
    if (!(loose > 0) || !std::isfinite(loose)) return std::numeric_limits<double>::infinity();
    return niceNumber(loose, true);
}

// Heckbert's step, then its nice neighbours (…, 0.1, 0.2, 0.5, 1, 2, …): the
// one whose ticks inside [lo, hi] come nearest `count` wins (the larger on a
// tie). Heckbert's loose labelling widens the axis to the ticks; a legend
// cannot, so a step that leaves two ticks inside is often too coarse. 0 when
// no step is usable.
double chooseStep(double lo, double hi, int count) {
    const double heckbert = heckbertStep(lo, hi, count);
    double step = 0;
    long long bestMiss = std::numeric_limits<long long>::max();
    if (const long long n = insideCount(lo, hi, heckbert); n >= 0) {
        step = heckbert;
        bestMiss = std::llabs(n - count);
    }
    // Without a finite Heckbert step the range is as wide as doubles go (the
    // steps near 10^307 decide) or narrower than normal doubles (those near its span).
    const int e = std::isfinite(heckbert) ? decade(heckbert) : std::isfinite(hi - lo) ? decade(hi - lo) : 307;
    for (int k = e - 1; k <= e + 1; ++k)
        for (const double m : {1.0, 2.0, 5.0}) {
            const double candidate = m * std::pow(10.0, k);
            const long long n = insideCount(lo, hi, candidate);
            if (n < 0) continue;
            const long long miss = std::llabs(n - count);
            if (miss < bestMiss || (miss == bestMiss && candidate > step)) {
                bestMiss = miss;
                step = candidate;
            }
        }
    return step;
}

}  // namespace

double niceNumber(double x, bool round) {
    const int e = decade(x);
    const double p = std::pow(10.0, e);
    const double f = scaleByDecade(x, e);
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
    const double reference = step > 0 && std::isfinite(step) ? step : (value != 0 ? std::fabs(value) : 1.0);
    const int stepDecade = decade(reference);
    if (!scientific) return fixed(value, -stepDecade);
    if (value == 0) return "0";
    // As many decimals as the step needs at the value's decade; again at the
    // decade rounding gave, when it moved (9.99 -> 10.0).
    const int e = decade(std::fabs(value));
    Scientific m = scientificDigits(value, e - stepDecade);
    if (m.exponent != e) m = scientificDigits(value, m.exponent - stepDecade);
    const std::string sign = value < 0 ? kMinus : "";
    return sign + (m.mantissa == "1" ? "" : m.mantissa + "\u00d7") + "10" + superscript(m.exponent);
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
    count = std::clamp(count, 2, 1000);
    const double step = chooseStep(lo, hi, count);
    const double eps = step * 1e-9;
    if (step > 0) {
        const Multiples multiples = multiplesInside(lo, hi, step);
        const long long first = (long long)multiples.first, last = (long long)multiples.last;
        const bool scientific =
            std::max(std::fabs(double(first) * step), std::fabs(double(last) * step)) >= 1e5 || step < 1e-3;
        for (long long k = first; k <= last; ++k) {
            double v = double(k) * step;
            if (std::fabs(v) < eps) v = 0;  // no "-0"
            // k × step rounds past an end when the values lie 10^13 steps from zero.
            if (v < lo - eps || v > hi + eps) continue;
            ticks.push_back({v, position(v, minimum, maximum), formatTickLabel(v, step, scientific)});
        }
    }
    if (ticks.empty()) {
        // No round step between two numbers this close (a span below 10^-300,
        // or a few units in the last place of the values): a tick at each end.
        const double span = hi / 2 - lo / 2;
        for (const double v : {lo, hi})
            ticks.push_back({v, position(v, minimum, maximum), formatTickLabel(v, span, true)});
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
        const double m = scaleByDecade(v, e);
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
