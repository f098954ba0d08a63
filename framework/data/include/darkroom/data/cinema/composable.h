#pragma once
// Composable image sets (CIS): databases in which each data.csv row is one
// channel of one layer of one image, as TTK, Ascent and ParaView write them:
//
//   object,FILE,CISVersion,CISImage,CISImageWidth,CISImageHeight,CISLayer,
//   CISLayerWidth,CISLayerHeight,CISLayerOffsetX,CISLayerOffsetY,CISChannel,
//   CISChannelVar,CISChannelColormap
//   000,000_Depth.npz,"1.0",i000,1024,1024,l000,1024,1024,0,0,CISDepth,Depth,
//
// A layer (typically one object) is assembled into one buffer whose channels
// are named by CISChannelVar, except depth, which becomes Darkroom's `Z`.
#include <darkroom/buffer.h>
#include <darkroom/export.h>
#include <darkroom/data/cinema/database.h>
#include <darkroom/diagnostics.h>

#include <memory>
#include <string>
#include <vector>

namespace darkroom {

struct CisChannel {
    std::size_t row = 0;     // data.csv row holding it
    std::string channel;     // CISChannel ("CISDepth", "Elevation", "CISShadow")
    std::string variable;    // CISChannelVar ("Depth", "Elevation", "SSSAO"); CISChannel when empty
    std::string colormap;    // absolute path of CISChannelColormap's JSON, "" when none
    bool isDepth = false;    // CISChannel "CISDepth" or variable "depth" (any case)
    std::string bufferName() const { return isDepth ? std::string("Z") : variable; }
};

struct CisLayer {
    std::string id;  // CISLayer
    int width = 0, height = 0, offsetX = 0, offsetY = 0;
    std::vector<CisChannel> channels;  // in data.csv order
    // The simple query that selects exactly this layer: "CISImage=i000, CISLayer=l000".
    std::string query;
    // Parameter (non-CIS, non-FILE) values shared by its rows: "object=000".
    std::string parameters;
};

struct CisImage {
    std::string id;  // CISImage
    int width = 0, height = 0;
    // The corner where pixel (0, 0) of every channel lies: "UL", "UR", "LL" or
    // "LR" (CISOrigin). "UL" when data.csv has no CISOrigin (originStated false).
    std::string origin = "UL";
    bool originStated = false;
    std::vector<CisLayer> layers;  // in order of first appearance
};

// True when the database has the CISImage, CISLayer and CISChannel columns.
DARKROOM_API bool isComposableImageSet(const CinemaDatabase& db);

// Groups `rows` (all rows when empty) into images and layers, in order of
// first appearance. Throws darkroom::Error naming data.csv:line when a row
// lacks its image, layer or channel, or sizes are not positive integers.
DARKROOM_API std::vector<CisImage> composableImages(const CinemaDatabase& db,
                                                    const std::vector<std::size_t>& rows = {});

// Reads every channel of one layer into a buffer of the IMAGE's size, the
// layer placed at its offset (pixels outside it: Z = +inf, other channels
// NaN). Channel arrays are indexed [x][y] (.npy shape = width, height) with y
// counted from the CISOrigin corner (UL when absent), as the CIS specification
// and cinemasci's renderer read them; the buffer has rows top to bottom.
// A file whose shape, dtype or members disagree with data.csv is an error
// naming the file, the data.csv line and column and what was expected.
// Depth becomes `Z`:
// - TTK (values in [0,1], background exactly 1.0): 1.0 -> +inf; with the
//   camera's near/far known (columns CamNear/CamFar or CamNearFar_0/_1)
//   Z = near + d (far - near), planar world depth; without them the
//   normalised values are kept (their ordering still composites correctly)
//   and "depth.convention" says so (no warning: the depth-based passes read
//   such Z in image space and say what they assume, see depth_input.h).
// - Ascent (NaN background): NaN -> +inf, distances kept.
// Metadata attributes: "colormap.<var>" = colour-map JSON path,
// "cis.image", "cis.layer", "cis.origin" (with "(assumed)" when data.csv does
// not say), "source", "depth.convention" (how Z was made).
DARKROOM_API std::shared_ptr<WritableBuffer> readComposableLayer(const CinemaDatabase& db,
                                                                 const CisImage& image,
                                                                 const CisLayer& layer,
                                                                 Diagnostics* warnings = nullptr);

// The layer that `rows` (e.g. the rows matched by "object=000") belong to.
// Throws darkroom::Error listing the layers when the rows span several layers
// or none ("use CISLayer=... or a parameter that picks one object").
DARKROOM_API std::shared_ptr<WritableBuffer> readComposableRows(const CinemaDatabase& db,
                                                                const std::vector<std::size_t>& rows,
                                                                Diagnostics* warnings = nullptr);

}  // namespace darkroom
