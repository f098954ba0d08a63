#pragma once
// What a depth-based pass (SSAO, Normals, SSDoF, Lighting, SSDD, IBS, EDL and
// third-party passes) reads of its input: the depth plane, and the camera that
// turns it into view-space positions. One home for both, so every pass makes
// the same assumption when the image carries no camera.
//
// Databases written by TTK, Ascent and ParaView store no camera. As TTK's own
// Darkroom filters do, a pass then shades in IMAGE SPACE: an orthographic
// camera made from the image size and the depth range (docs/cameras.md):
//
//   view height  H = the depth range: 1 for depth normalised to [0, 1]
//                    (TTK), max - min of the finite Z for raw distances
//                    (1 when that is not positive);
//   pixel centre (x + 0.5, y + 0.5) -> world ((x + 0.5 - W/2) H/h,
//                    (h/2 - y - 0.5) H/h, -Z): the camera sits at the origin,
//                    looks along -z with +y up, and Z is kept as it is.
//
// So a radius given as a fraction of the image height means the same on every
// image, and depth and image extent are in one unit. One warning per node and
// sequence (a `run --foreach` over N entries says it once) says what was assumed.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/export.h>
#include <darkroom/port.h>

#include <atomic>
#include <string>

namespace darkroom {

// How Z is read when the image carries no camera.
enum class DepthWithoutCamera {
    Automatic,   // Normalised when every finite Z lies in [0, 1], else Raw
    Normalised,  // depth normalised to [0, 1] between near and far (TTK's CinemaImaging)
    Raw,         // distances in some unknown unit (Ascent, ParaView)
};

// The image-space assumption for one image.
struct ImageSpaceView {
    Camera camera;            // orthographic, the image's resolution
    bool normalised = true;   // how Z was read
    bool decidedByValues = false;  // Automatic chose `normalised` from the values
    double zMin = 0, zMax = 0;     // finite Z of the image (0, 0 when none)
    // What was assumed, in the words of the pass's warning.
    DARKROOM_API std::string describe() const;
};

// The orthographic camera described above, for a width x height image whose
// view is `viewHeight` units high.
DARKROOM_API Camera imageSpaceCamera(int width, int height, double viewHeight);

// The assumption for an image of size width x height with depth `z`
// (pixelCount values; +inf, NaN = no surface).
DARKROOM_API ImageSpaceView assumeImageSpace(const float* z, int width, int height, DepthWithoutCamera mode);

// The float32 depth plane `Z` of a depth-based pass's input. Without one,
// throws darkroom::Error saying which database or file stores no depth
// (from the buffer's "source" attribute) and listing the channels it has.
DARKROOM_API const float* requireDepth(const Buffer& in);
// requireDepth's message for a buffer without a float32 `Z` (the host says
// the same when an image port that needs `Z` gets none).
DARKROOM_API std::string missingDepthMessage(const Buffer& in);

// The camera of a buffer with the buffer's resolution when it has one;
// otherwise the image-space camera for its depth `z`, and `assumption` (if not
// null) receives what was assumed, for a warning.
DARKROOM_API Camera cameraOrImageSpace(const Buffer& in, const float* z, DepthWithoutCamera mode,
                                       std::string* assumption);

// What a depth-based pass keeps to get its camera: the port that says how to
// read Z without one, and whether this sequence has said its assumption.
// Declare one as a member, list port() among the ports, call
// beginSequence() from Filter::beginSequence and get() in execute().
class CameraSource {
public:
    const EnumIn<DepthWithoutCamera>& port() const { return port_; }
    void beginSequence() { said_.store(false); }
    // The image's camera, or the image-space one, saying so once per sequence.
    Camera get(Context& ctx, const Buffer& in, const float* z) {
        std::string assumption;
        const Camera c = cameraOrImageSpace(in, z, ctx.get(port_), &assumption);
        if (!assumption.empty() && !said_.exchange(true)) ctx.warn(assumption);
        return c;
    }

private:
    EnumIn<DepthWithoutCamera> port_{
        "depthWithoutCamera",
        {{DepthWithoutCamera::Automatic, "auto"},
         {DepthWithoutCamera::Normalised, "normalised"},
         {DepthWithoutCamera::Raw, "raw"}},
        DepthWithoutCamera::Automatic,
        "Only for an image without a camera (TTK, Ascent, ParaView databases), which is shaded in image space with "
        "an orthographic camera as high as the depth range: normalised: Z is depth normalised to [0, 1] (TTK), the "
        "view is 1 unit high; raw: Z is a distance, the view is as high as the image's Z range (max - min); auto: "
        "normalised when every finite Z lies in [0, 1], else raw"};
    std::atomic<bool> said_{false};
};

}  // namespace darkroom
