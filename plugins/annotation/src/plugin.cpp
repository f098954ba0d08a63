#include "annotation.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Annotation>(
        "Annotation", "Annotation",
        "Text over the image: one or more lines at an anchor (corner, edge or centre) with a margin and an offset, "
        "in a given size, colour and font, optionally on a box; placeholders such as {time} or {phi:.0f} are "
        "filled from the Cinema row being shaded (connect CinemaReader's row). Text through pango and cairo at "
        "the image's resolution.");
}

}  // namespace

DARKROOM_PLUGIN("annotation", "0.1.0", registerTypes)
