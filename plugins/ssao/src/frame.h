#pragma once
// SSAO's per-pixel view-space geometry, computed once and read by the
// estimators and the blur: structure-of-arrays planes (depth, 1/depth, the
// normal's three components) with a border of padding, so SIMD kernels read
// whole vectors and neighbours without bounds checks. Projection and
// unprojection are the SDK's (darkroom/view_geometry.h): x right, y up,
// z = planar depth forward.
#include <darkroom/buffer.h>
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/view_geometry.h>

#include <cstddef>
#include <cstdint>
#include <memory>

namespace darkroom::ssao {

// Every plane holds (height + 2 padY) rows of `stride` floats; pixel (x, y)
// is at offset(x, y). Padding and the tail of each row beyond the width read
// as "no surface". Rows start 64-byte aligned. The planes come from the
// host's pool (Context::allocate), so repeated runs reuse their memory.
struct Frame : ViewGeometry {
    int padX = 0, padY = 0, stride = 0;
    float* z = nullptr;            // planar depth; +inf where there is no surface
    float* f = nullptr;            // 1/z (perspective) or z (orthographic); -inf where no surface
    float* n[3] = {nullptr, nullptr, nullptr};  // unit view-space normal facing the camera; 0 where no surface

    // Constants of the image-plane mapping: view-plane x = sx(px) = ax px + bx
    // at unit depth (perspective) or in world units (orthographic), likewise y.
    float ax = 0, bx = 0, ay = 0, by = 0;
    float pixelScale = 0;  // pixelSizeAt(z) = pixelScale * z (perspective) or pixelScale

    Frame(const Camera& camera, int width, int height, int border);

    std::size_t offset(int x, int y) const {
        return std::size_t(y + padY) * std::size_t(stride) + std::size_t(x + padX);
    }
    std::size_t planeSize() const { return std::size_t(height() + 2 * padY) * std::size_t(stride); }

    // `count` planes of this layout from the host's pool, uninitialised; they
    // live as long as the returned buffer.
    std::shared_ptr<WritableBuffer> allocatePlanes(Context& ctx, int count) const;
    // Sets the padding of rows [y0, y1) of `plane` (left of x = 0 and right of
    // the width) to `value`; rows outside [0, height) are filled whole.
    void fillPadding(float* plane, int y0, int y1, float value) const;

    std::shared_ptr<WritableBuffer> storage;  // z, f and the normals
};

// Builds the depth planes and normals. Normals come from the input's
// N.x/N.y/N.z (world space, rotated into view space) when useNormals is set
// and they are present and finite, otherwise from depth differences with the
// neighbour on the side whose depth is closer (so depth edges do not bend the
// normal). `border` is the padding the later kernels need (the blur radius).
Frame buildFrame(const Buffer& in, const Camera& camera, bool useNormals, int border, Context& ctx);

}  // namespace darkroom::ssao
