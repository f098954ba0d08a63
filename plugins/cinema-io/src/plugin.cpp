#include "cinema_reader.h"

#include <darkroom/plugin.h>

namespace {

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<darkroom::CinemaReader>(
        "CinemaReader", "Input/Output",
        "Reads one entry of a Cinema Spec D database, chosen by parameter values "
        "('phi=30, theta=45'), and outputs its product image. Tolerates the data.csv "
        "variants real databases contain (FILE columns anywhere, quoted numbers, NaN, "
        "empty cells, uneven rows) and warns about them.");
}

}  // namespace

DARKROOM_PLUGIN("cinema-io", "0.1.0", registerTypes)
