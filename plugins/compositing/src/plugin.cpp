#include "compositing.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Compositing>(
        "Compositing", "Compositing",
        "Merges any number of G-buffers of the same size by depth: per pixel the input with the smallest "
        "finite depth wins and brings every channel with it. The output has the union of the inputs' "
        "channels (a channel the winning input lacks is NaN, or 0xFFFFFFFF for uint32); ties go to the "
        "lower input index; background (depth +inf or NaN) never wins, and a pixel that is background "
        "in every input gets Z = +inf, transparent black R, G, B, A and NaN in other channels. The "
        "first input's camera is kept.");
}

}  // namespace

DARKROOM_PLUGIN("compositing", "0.1.0", registerTypes)
