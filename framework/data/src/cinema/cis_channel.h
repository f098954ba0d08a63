#pragma once
// One channel file of a composable image set, read by the CIS convention and
// checked against what data.csv says about it.
//
// The convention (cinemascience/cinema, specs/dietrich/01/extensions/cis/1.0
// and cinemasci's reference renderer, cinemasci/cis/renderer.py): a channel is
// a W x H array indexed [x][y], so the .npy shape is (width, height); the
// canvas is (image width, image height) and a layer's offset (X, Y) indexes
// it the same way. y counts from the image's origin corner (CISOrigin: UL, UR,
// LL or LR; UL where the column is absent, as in the keyword table and in what
// cinemasci draws). Darkroom's buffers are rows top to bottom, so the channel
// is transposed, and flipped for the LL/LR/UR origins, on reading.
#include <darkroom/data/cinema/composable.h>
#include <darkroom/diagnostics.h>
#include <darkroom/data/formats/npy.h>

#include <string>
#include <vector>

namespace darkroom::cis {

// The values of one channel of `layer`, layer.width * layer.height of them,
// stored [x][y]: value (x, y) at index x * layer.height + y, y counted from the
// image's origin corner. Throws darkroom::Error naming the file, the data.csv
// line and column and what was expected when the file's shape, dtype or
// member names disagree with data.csv; `warnings` receives the variants that
// are read anyway (an integer array where the type is not stated, a member not
// named 'data').
std::vector<float> readChannelValues(const CinemaDatabase& db, const CisImage& image, const CisLayer& layer,
                                     const CisChannel& channel, Diagnostics* warnings);

// The member of a channel .npz that holds `ch` ('data', or the only one),
// checked against data.csv: shape (layer width, layer height), dtype against
// CISChannelVarType. Works on headers alone (readNpzHeaders) as well as on
// whole arrays. Throws as readChannelValues does.
const NpyArray& checkedMember(const CinemaDatabase& db, const CisLayer& layer, const CisChannel& ch,
                              const std::string& path, const std::vector<NpyArray>& members, Diagnostics* warnings);

// Writes layer values stored [x][y] (as above) into an image-sized buffer
// plane with rows top to bottom, following the image's origin and the
// layer's offset. Pixels outside the layer are left as they are.
void placeLayer(const std::vector<float>& values, const CisImage& image, const CisLayer& layer, float* plane);

// "UL", "UR", "LL" or "LR" from a CISOrigin cell (any case, surrounding
// spaces ignored); throws naming the file, line and column otherwise.
std::string parseOrigin(const CinemaDatabase& db, std::size_t row);

}  // namespace darkroom::cis
