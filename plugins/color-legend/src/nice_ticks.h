#pragma once
// Where a colour legend puts its tick marks and what it writes there: values
// at round numbers ("nice numbers", Heckbert, Graphics Gems 1990: steps of 1, 2
// or 5 times a power of ten) inside the mapped range, or decades on a log scale.
#include <string>
#include <vector>

namespace darkroom::legend {

struct Tick {
    double value = 0;
    double t = 0;  // position along the bar, 0 at `minimum`, 1 at `maximum`
    std::string label;
};

// Heckbert's nice number near x > 0: 1, 2, 5 or 10 times a power of ten,
// rounded to the nearest (round) or the next at or above (ceiling).
double niceNumber(double x, bool round);

// About `count` ticks at multiples of a nice step, every one inside the range
// [min(minimum, maximum), max(...)] (ends included within a 1e-9 step
// tolerance), in increasing value. The step is Heckbert's or the nice number
// near it (1, 2, 5 × 10^k within a decade) whose ticks inside the range come
// nearest `count`, the larger step on a tie. A range of zero width gets one tick at the
// value; a range too narrow for any round step between its ends (a span below
// 10^-300, or steps so small next to the values that k × step would not be
// distinct doubles) a tick at each end. Every finite range, however wide or
// narrow, gets ticks; a range that is not finite none. Labels show as many
// decimals as the step needs ("0.2", "−2", "1500", with a typeset minus sign
// U+2212); when a tick reaches 10^5 or the step is below 10^-3, every label is in
// scientific notation with a Unicode superscript exponent ("2.5×10⁻⁴").
std::vector<Tick> linearTicks(double minimum, double maximum, int count);

// Log scale (minimum, maximum > 0, else darkroom::Error): ticks at powers of
// ten inside the range, every k-th decade when there are many; when fewer than
// three powers of ten lie inside, at 1, 2, 5 times powers of ten; failing
// that, at linear nice numbers. `t` is the position in log10.
std::vector<Tick> logTicks(double minimum, double maximum, int count);

// A label for `value` (finite) when ticks are `step` apart: fixed notation
// with the step's decimals, or, when `scientific`, mantissa × 10 to a
// superscript power, the mantissa with the decimals the step needs (at most 16).
// Built from the digits of |value| and its sign; no label is ever read back
// as a number.
std::string formatTickLabel(double value, double step, bool scientific);

// "10⁻³"-style superscript digits for an integer exponent.
std::string superscript(int exponent);

}  // namespace darkroom::legend
