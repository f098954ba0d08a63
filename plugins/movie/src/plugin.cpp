#include "movie.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::Movie>(
        "Movie", "Input/Output",
        "Writes an MP4 (H.264, through FFmpeg's libraries) of the pictures of a Cinema database, one frame per "
        "entry in the entries' sorted order, at a frame rate and quality: the movie of a `darkroom run --foreach` "
        "whose frames a CinemaWriter wrote (it runs once, after the last entry).");
}

}  // namespace

DARKROOM_PLUGIN("movie", "0.1.0", registerTypes)
