#pragma once
// Checking that a database's files agree with its data.csv, product by
// product, without reading pixel data (headers only): for `darkroom info`.
#include <darkroom/export.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/diagnostics.h>

namespace darkroom {

// One diagnostic per disagreement, each naming the file, the data.csv line and
// column and what was expected:
// - every FILE cell names an existing file;
// - Spec D: the products of one FILE column share the size and channel names
//   of the column's first product (a Cinema viewer shows them in one frame);
// - composable image sets: each channel .npz holds a 'data' member whose shape
//   is the layer's (width, height) ([x][y]) and whose dtype agrees with
//   CISChannelVarType (float by default).
// Missing files and CIS shape/type disagreements are errors (reading that
// entry fails); a Spec D product of another size is a warning (it reads, but
// not like its neighbours).
DARKROOM_API Diagnostics checkProductFiles(const CinemaDatabase& db);

}  // namespace darkroom
