#include "cinema_writer_node.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::CinemaWriterNode>(
        "CinemaWriter", "Input/Output",
        "Writes its input as one entry of a Cinema Spec D database (PNG pictures or EXR G-buffers), the entry's "
        "columns copied from the CinemaReader row being shaded: `darkroom run --foreach` of a pipeline ending here "
        "shades a whole database into a new, browsable one. Atomic, resumable and locked like darkroom capture.");
}

}  // namespace

DARKROOM_PLUGIN("cinema-writer", "0.1.0", registerTypes)
