#pragma once
// View-space reconstruction of the G-buffer: positions and normals from depth
// and the camera, and the projection back to pixels that the estimators use
// to find occluders. View space: x right, y up, z = planar view depth
// (forward, positive in front of the camera).
#include "vec3f.h"

#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>

#include <cstdint>
#include <vector>

namespace darkroom::ssao {

struct ViewGeometry {
    int width = 0, height = 0;
    bool perspective = true;
    float halfWidth = 1, halfHeight = 1;  // image-plane half extents (see Camera::planeOffsets)
    std::vector<V3> position;             // view-space position per pixel centre
    std::vector<V3> normal;               // unit, facing the camera
    std::vector<std::uint8_t> valid;      // finite depth in front of the camera

    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width) + std::size_t(x); }

    // World size of one pixel at planar depth z (Camera::pixelSizeAt).
    float pixelSizeAt(float z) const {
        const float h = 2.0f * halfHeight / float(height);
        return perspective ? h * z : h;
    }
    // Unit vector from view-space point p toward the camera.
    V3 toCamera(V3 p) const { return perspective ? normalize(p * -1.0f) : V3{0, 0, -1}; }
    // View-space point at continuous pixel coordinates (px, py) and planar depth z.
    V3 unproject(float px, float py, float z) const {
        const float sx = (2.0f * px / float(width) - 1.0f) * halfWidth;
        const float sy = (1.0f - 2.0f * py / float(height)) * halfHeight;
        return perspective ? V3{sx * z, sy * z, z} : V3{sx, sy, z};
    }
    // Continuous pixel coordinates (top-left origin) of view-space point q;
    // false when q is not in front of a perspective camera.
    bool project(V3 q, float& px, float& py) const {
        float sx = q.x, sy = q.y;
        if (perspective) {
            if (!(q.z > 0)) return false;
            sx /= q.z;
            sy /= q.z;
        }
        px = (sx / halfWidth + 1.0f) * 0.5f * float(width);
        py = (1.0f - sy / halfHeight) * 0.5f * float(height);
        return true;
    }

    // The surface point seen at continuous pixel coordinates (px, py): depth
    // interpolated between the four surrounding pixel centres (1/z for
    // perspective, z for orthographic, both exactly linear on screen for a
    // plane) when they are valid and within 4 pixel sizes of each other, else the
    // nearest pixel's point. False when the nearest pixel has no valid depth.
    bool surfaceAt(float px, float py, V3& out) const;
};

// Builds positions and normals. Normals come from the input's N.x/N.y/N.z
// (world space, rotated into view space) when useNormals is set and they are
// present and finite, otherwise from depth differences with the neighbour on
// the side whose depth is closer (so depth edges do not bend the normal).
ViewGeometry buildViewGeometry(const Buffer& in, const Camera& camera, bool useNormals, Context& ctx);

}  // namespace darkroom::ssao
