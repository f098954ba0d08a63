// ColorLegend's text (plugins/color-legend): the tick choice and labels of
// linearTicks and logTicks for a range, then a labelFormat applied to them.
// The input is text: "minimum maximum count" on the first line (strtod, so
// inf, nan and hexadecimal too), the labelFormat on the rest. Beyond not
// crashing: ticks lie inside the range in increasing order, their labels are
// short and never "inf" or "nan", formatted labels stay within the limits.
#include "harness.h"

#include "label_format.h"
#include "nice_ticks.h"
#include <darkroom/text/text_limits.h>

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

namespace {

void checkTicks(const std::vector<darkroom::legend::Tick>& ticks, double lo, double hi) {
    fuzz::expect(ticks.size() <= 1000, "at most 1000 ticks");
    for (std::size_t i = 0; i < ticks.size(); ++i) {
        const auto& t = ticks[i];
        fuzz::expect(std::isfinite(t.value), "tick values are finite");
        // Ends within the documented 1e-9-step tolerance; t is the position on the bar.
        fuzz::expect(t.t >= -1e-6 && t.t <= 1 + 1e-6, "ticks lie on the bar");
        // Inside within a millionth of the span (the ends' tolerance is 1e-9
        // of a step), or of the values for a span too narrow for a step.
        const double slack = std::fmax(hi / 2 - lo / 2, std::fmax(std::fabs(lo), std::fabs(hi)) * 1e-9) * 2e-6;
        fuzz::expect(t.value >= lo - slack && t.value <= hi + slack, "ticks lie inside the range");
        fuzz::expect(i == 0 || t.value > ticks[i - 1].value, "ticks increase");
        fuzz::expect(!t.label.empty() && t.label.size() <= 80, "labels are short and not empty");
        fuzz::expect(t.label.find("inf") == std::string::npos && t.label.find("nan") == std::string::npos,
                     "labels are numbers");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string input(fuzz::text(data, size));
    const std::size_t newline = input.find('\n');
    const std::string numbers = input.substr(0, newline);
    const std::string spec = newline == std::string::npos ? "" : input.substr(newline + 1);
    const char* p = numbers.c_str();
    char* end = nullptr;
    const double minimum = std::strtod(p, &end);
    const double maximum = std::strtod(end, &end);
    const long count = std::strtol(end, &end, 10);
    const int ticksWanted = int(std::clamp(count, 2L, 20L));  // the node's `ticks` port range
    const double lo = std::fmin(minimum, maximum), hi = std::fmax(minimum, maximum);

    auto ticks = darkroom::legend::linearTicks(minimum, maximum, ticksWanted);
    if (std::isfinite(minimum) && std::isfinite(maximum)) {
        fuzz::expect(!ticks.empty(), "a finite range has ticks");
        checkTicks(ticks, lo, hi);
    } else {
        fuzz::expect(ticks.empty(), "a range that is not finite has no ticks");
    }
    try {
        checkTicks(darkroom::legend::logTicks(minimum, maximum, ticksWanted), lo, hi);
    } catch (const darkroom::Error&) {
        fuzz::expect(!(lo > 0 && std::isfinite(hi)), "a positive finite range has log ticks");
    }
    if (spec.empty()) return 0;
    try {
        darkroom::legend::applyLabelFormat(ticks, spec);
        for (const auto& t : ticks)
            // Padding to at most kMaxFormatWidth characters of a fill that
            // UTF-8 writes in up to 4 bytes ("\xe7\xe7\xe7>1000g" pads with a
            // 3-byte character: 3,000 bytes), plus the number itself.
            fuzz::expect(t.label.size() <= 4 * darkroom::text::kMaxFormatWidth + 400, "formatted labels are bounded");
    } catch (const darkroom::Error&) {
    }
    return 0;
}
