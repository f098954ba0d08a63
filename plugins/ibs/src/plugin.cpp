#include "ibs.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Ibs>(
        "IBS", "Shading",
        "Image-based silhouettes: outlines where depth jumps by more than a relative threshold "
        "(and where objectId changes), of a given width, colour and strength, drawn on the nearer "
        "(default) or farther side; optionally the headlight lighting term luminance * (ambient + "
        "(1 - ambient) max(0, N.V)). Adds the channel Silhouette.");
}

}  // namespace

DARKROOM_PLUGIN("ibs", "0.1.0", registerTypes)
