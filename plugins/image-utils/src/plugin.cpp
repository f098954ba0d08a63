#include "background.h"
#include "channel_select.h"
#include "mix.h"
#include "resize.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Mix>(
        "Mix", "Color",
        "Combines a colour image with a factor channel or a second image. multiply scales R, G, B by a channel "
        "such as AO or SSDD (from 'other' or the image itself; background and NaN factors are left alone); "
        "blend interpolates; over composites 'other' over the image with its straight alpha; add adds. "
        "Every other channel of the image passes through.");
    r.addFilter<darkroom::Background>(
        "Background", "Color",
        "Puts a colour or a vertical gradient (top row to bottom row) behind the scene: the image, with "
        "straight alpha A (or depth as coverage), composited over it. Other channels pass through.");
    r.addFilter<darkroom::ChannelSelect>(
        "ChannelSelect", "Image",
        "Keeps the listed channels in the listed order, renaming with SOURCE:NEWNAME (e.g. \"value:R\"), or "
        "drops them. A missing channel is an error listing those the image has.");
    r.addFilter<darkroom::Resize>(
        "Resize", "Image",
        "Resamples an image to a new size (box, bilinear or nearest) for previews and supersampled "
        "references. Colour and scalars are filtered, colour weighted by alpha, NaN skipped; depth Z and uint32 "
        "ids are never blended: they come from the nearest surface in a box footprint or from the nearest "
        "pixel. The camera's resolution is updated.");
}

}  // namespace

DARKROOM_PLUGIN("image-utils", "0.1.0", registerTypes)
