#pragma once
// TTK's `.vti` products: VTK XML ImageData as ttkCinemaImaging writes it, one
// image per file with the rendered point arrays (Depth, scalars, ids) and the
// camera in the field data.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/export.h>
#include <darkroom/diagnostics.h>

#include <memory>
#include <optional>
#include <string>

namespace darkroom {

// TTK's camera model as stored in the field data of its images.
struct TtkCamera {
    Vec3 position{0, 0, 1};
    Vec3 direction{0, 0, -1};  // CamDirection, or CamFocalPoint - CamPosition
    Vec3 up{0, 1, 0};
    bool orthographic = true;  // ProjectionMode 0 = orthographic, 1 = perspective
    double viewHeight = 1;     // CamHeight: orthographic view height
    double angle = 90;         // CamAngle: perspective angle in degrees (see below)
    double nearPlane = 0, farPlane = 0;  // CamNearFar; both 0 = depth not normalised
    int width = 0, height = 0;           // image size in pixels
};

// Darkroom's camera for a TTK camera. TTK spreads perspective rays LINEARLY
// in angle: pixel x of W gets the direction forward + (x - W/2) * (angle_rad /
// W) * right (and the same step vertically), i.e. the image plane at unit
// distance is angle_rad wide. Darkroom's perspective camera is a pinhole with
// tan(fovY/2) = half-height at unit distance, so fovY = 2 atan(angle_rad/2 *
// H/W). TTK's perspective rays go through pixel corners (no half-pixel offset);
// Darkroom's through centres: a shift of half a pixel, not representable.
DARKROOM_API Camera toDarkroomCamera(const TtkCamera& ttk);

// TTK's normalised depth d in [0,1] (ttkCinemaImaging::Normalize: planar
// depth (t of an unnormalised ray whose forward component is 1) mapped from
// [near, far] to [0, 1], clamped, no hit = 1.0) back to planar world depth:
// near + d (far - near), and 1.0 -> +inf. Without near/far (both 0) TTK
// stores planar depth as is, NaN for no hit: NaN -> +inf.
DARKROOM_API float ttkDepthToPlanar(float d, double nearPlane, double farPlane);

struct VtiImage {
    // One float32 channel per point array (multi-component arrays become
    // "name.0", "name.1", ...), rows flipped to a top-left origin (VTK images
    // start at the bottom row). The array named Depth (any case) becomes Z
    // through ttkDepthToPlanar when it is TTK's depth. The camera, when the
    // field data holds one, is in metadata().camera.
    std::shared_ptr<WritableBuffer> buffer;
    std::optional<TtkCamera> ttkCamera;
    Diagnostics warnings;  // conversions stated (e.g. depth kept normalised)
};

// Reads a VTK XML ImageData file (ascii, inline base64, appended raw or
// base64; zlib or not). Throws darkroom::Error naming file:line.
DARKROOM_API VtiImage readVti(const std::string& path);

// Writes a VTK XML ImageData file of `image`'s float channels as point arrays
// (appended raw, uncompressed; rows flipped back to VTK's bottom-up order),
// with `camera` as TTK field data when given. Z is written as TTK's
// normalised "Depth" when the camera has near < far, else as "Depth" planar.
// Written atomically. Used by tests and for exchange with TTK.
struct VtiWriteOptions {
    bool base64 = false;  // appended data base64-encoded instead of raw
    bool zlib = false;    // vtkZLibDataCompressor blocks
};
DARKROOM_API void writeVti(const std::string& path, const Buffer& image,
                           const std::optional<TtkCamera>& camera = std::nullopt,
                           const VtiWriteOptions& options = {});

}  // namespace darkroom
