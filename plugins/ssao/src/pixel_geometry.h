#pragma once
// SSAO's per-pixel view-space geometry: positions and normals of every pixel,
// computed once and read by the estimators and the blur. Projection and
// unprojection are the SDK's (darkroom/view_geometry.h), so SSAO shares one
// convention with every other pass: x right, y up, z = planar depth forward.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/view_geometry.h>

#include <cstdint>
#include <vector>

namespace darkroom::ssao {

struct PixelGeometry : ViewGeometry {
    std::vector<V3f> points;          // view-space position of every pixel centre
    std::vector<V3f> normal;          // unit, facing the camera
    std::vector<std::uint8_t> valid;  // finite depth in front of the camera

    PixelGeometry(const Camera& camera, int width, int height) : ViewGeometry(camera, width, height) {}

    std::size_t index(int x, int y) const { return std::size_t(y) * std::size_t(width()) + std::size_t(x); }

    // The surface point seen at continuous pixel coordinates (px, py): depth
    // interpolated between the four surrounding pixel centres (1/z for
    // perspective, z for orthographic, both exactly linear on screen for a
    // plane) when they are valid and within 4 pixel sizes of each other, else the
    // nearest pixel's point. False when the nearest pixel has no valid depth.
    bool surfaceAt(float px, float py, V3f& out) const;
};

// Builds positions and normals. Normals come from the input's N.x/N.y/N.z
// (world space, rotated into view space) when useNormals is set and they are
// present and finite, otherwise from depth differences with the neighbour on
// the side whose depth is closer (so depth edges do not bend the normal).
PixelGeometry buildPixelGeometry(const Buffer& in, const Camera& camera, bool useNormals, Context& ctx);

}  // namespace darkroom::ssao
