#pragma once
// The legend's `labelFormat`: tick labels written with a format specification
// of the user's (fmt / Python syntax, ".2f", ".1e", "g"). Pure text (fmt, no
// pango), so the fuzz harness tests/fuzz/harnesses/legend.cpp compiles it.
#include "nice_ticks.h"

#include <string>
#include <vector>

namespace darkroom::legend {

// Replaces every tick's label with its value formatted by `spec` (non-empty).
// Throws darkroom::Error naming labelFormat for an unknown or non-float
// presentation type, braces, a width or precision above text::kMaxFormatWidth
// (text_limits.h), or anything else fmt refuses.
void applyLabelFormat(std::vector<Tick>& ticks, const std::string& spec);

}  // namespace darkroom::legend
