#pragma once
// View-space geometry of a depth buffer: positions from depth, normals
// reconstructed from depth, the world footprint of a pixel. One convention for
// every pass (SSAO, Normals, SSDoF, IBS, SSDD and third-party passes):
//
//   view space: x to the right, y up, z = planar depth along the camera's
//   forward axis, positive in front of the camera (Darkroom's Z channel).
//   Pixel (0, 0) is the top-left pixel; its centre is at (0.5, 0.5).
//
// Single-precision helpers for per-pixel loops are inline; the normal
// reconstruction is in the SDK library.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/export.h>

#include <cmath>
#include <string>
#include <vector>

namespace darkroom {

// A single-precision 3-vector for inner loops (Vec3 is double, which halves
// the throughput of sampling loops).
struct V3f {
    float x = 0, y = 0, z = 0;
};
inline V3f operator+(V3f a, V3f b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
inline V3f operator-(V3f a, V3f b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline V3f operator*(V3f a, float s) { return {a.x * s, a.y * s, a.z * s}; }
inline float dot(V3f a, V3f b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
inline V3f cross(V3f a, V3f b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline float length(V3f a) { return std::sqrt(dot(a, a)); }
inline V3f normalize(V3f a) {
    const float l = length(a);
    return l > 0 ? a * (1.0f / l) : a;
}

// True where a depth is usable surface: finite (+inf is background; NaN and
// -inf are treated as no data too).
inline bool isSurface(float z) { return z - z == 0.0f; }

// The camera of a buffer with the buffer's resolution (a resized image keeps
// its view). Throws darkroom::Error naming `what` (e.g. "input 'image'") when
// the buffer carries no camera.
DARKROOM_API Camera requireCamera(const Buffer& in, const std::string& what);

// Projection between pixels and view space for one camera and image size.
class ViewGeometry {
public:
    ViewGeometry() = default;
    ViewGeometry(const Camera& camera, int width, int height)
        : width_(width), height_(height), perspective_(camera.projection == Camera::Projection::Perspective) {
        halfHeight_ = float(camera.halfHeight());
        halfWidth_ = halfHeight_ * float(width) / float(height > 0 ? height : 1);
        camera.basis(right_, up_, forward_);
    }

    int width() const { return width_; }
    int height() const { return height_; }
    bool perspective() const { return perspective_; }
    // Image-plane half extents at unit depth (perspective) or in world units
    // (orthographic); see Camera::planeOffsets.
    float halfWidth() const { return halfWidth_; }
    float halfHeight() const { return halfHeight_; }

    // View-space point at continuous pixel coordinates (px, py) and planar depth z.
    V3f unproject(float px, float py, float z) const {
        const float sx = (2.0f * px / float(width_) - 1.0f) * halfWidth_;
        const float sy = (1.0f - 2.0f * py / float(height_)) * halfHeight_;
        return perspective_ ? V3f{sx * z, sy * z, z} : V3f{sx, sy, z};
    }
    // View-space point of the centre of pixel (x, y) at planar depth z.
    V3f position(int x, int y, float z) const { return unproject(float(x) + 0.5f, float(y) + 0.5f, z); }
    // Continuous pixel coordinates of view-space point q; false when q is not
    // in front of a perspective camera.
    bool project(V3f q, float& px, float& py) const {
        float sx = q.x, sy = q.y;
        if (perspective_) {
            if (!(q.z > 0)) return false;
            sx /= q.z;
            sy /= q.z;
        }
        px = (sx / halfWidth_ + 1.0f) * 0.5f * float(width_);
        py = (1.0f - sy / halfHeight_) * 0.5f * float(height_);
        return true;
    }
    // World size of one pixel at planar depth z: the footprint of a pixel.
    float pixelSizeAt(float z) const {
        const float h = 2.0f * halfHeight_ / float(height_);
        return perspective_ ? h * z : h;
    }
    // Unit vector from view-space point p towards the camera.
    V3f toCamera(V3f p) const { return perspective_ ? normalize(p * -1.0f) : V3f{0, 0, -1}; }
    // A world-space direction in view space, and back.
    V3f toView(const Vec3& world) const {
        return V3f{float(dot(world, right_)), float(dot(world, up_)), float(dot(world, forward_))};
    }
    Vec3 toWorld(const Vec3& view) const { return right_ * view.x + up_ * view.y + forward_ * view.z; }

private:
    int width_ = 0, height_ = 0;
    bool perspective_ = true;
    float halfWidth_ = 1, halfHeight_ = 1;
    Vec3 right_{1, 0, 0}, up_{0, 1, 0}, forward_{0, 0, 1};
};

// How the tangent along each image axis is estimated from depth.
//   Central       (P[x+1] - P[x-1]) / 2: second-order on smooth surfaces,
//                 wrong across depth discontinuities.
//   Nearest       the one-sided difference towards the neighbour with the
//                 smaller depth difference.
//   Extrapolated  per side, predict the centre from two neighbours (linearly
//                 in 1/Z for perspective, in Z for orthographic cameras, the
//                 quantities that are affine in the image on a plane) and use
//                 the side that predicts it better; when both predict it
//                 equally well (within a factor 2), the central difference.
enum class NormalMethod { Central, Nearest, Extrapolated };

// Destinations, each may be null. Pixels without a surface get NaN.
struct NormalOutputs {
    float* view[3] = {nullptr, nullptr, nullptr};      // view-space normal (see above)
    float* world[3] = {nullptr, nullptr, nullptr};     // world-space normal
    float* position[3] = {nullptr, nullptr, nullptr};  // world-space position
    // Write the view normal's z towards the viewer instead (the OpenGL
    // normal-map convention of the Normals pass's Nv channels).
    bool viewZTowardsViewer = false;
};

// Unit normals facing the camera, computed in double precision. `camera` must
// have the buffer's resolution (requireCamera). An axis with no surface
// neighbour at all (a one-pixel-wide feature, a 1x1 image) takes the camera's
// own axis as tangent, i.e. the normal leans towards the viewer.
DARKROOM_API void reconstructNormals(Context& ctx, const float* depth, int width, int height, const Camera& camera,
                                     NormalMethod method, const NormalOutputs& out);

// World-space normals (captured N.*) rotated into view space.
DARKROOM_API void worldToViewNormals(Context& ctx, const float* const world[3], std::size_t count,
                                     const Camera& camera, float* const view[3], bool zTowardsViewer = false);

}  // namespace darkroom
