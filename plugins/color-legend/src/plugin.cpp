#include "color_legend.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::ColorLegend>(
        "ColorLegend", "Annotation",
        "A colour bar (horizontal or vertical, at a corner or a pixel position, sized relative to the image) "
        "with tick labels at round numbers, a title and units, drawn from the map, range and scale a "
        "ColorMapping used (connect its usedColormap, usedMinimum, usedMaximum, usedScale). Text through "
        "pango and cairo at the image's resolution.");
}

}  // namespace

DARKROOM_PLUGIN("color-legend", "0.1.0", registerTypes)
