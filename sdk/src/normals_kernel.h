#pragma once
// The normal reconstruction behind reconstructNormals (view_geometry.h),
// shared by its per-pixel code (image borders, short rows) and its SIMD code
// (normals_simd.cpp), which computes the same double-precision operations in
// the same order for several pixels at once, so both give the same bits.
#include <darkroom/camera.h>
#include <darkroom/view_geometry.h>

#include <vector>

namespace darkroom::normals {

// Per-column and per-row image-plane offsets in double precision, so the
// inner loop does no trigonometry or basis orthonormalisation.
struct PlaneOffsets {
    Vec3 right, up, forward, origin;
    bool perspective = true;
    std::vector<double> sx, sy;
    double pixelSize = 0;  // orthographic pixel size (world units)

    PlaneOffsets(const Camera& c, int w, int h);

    // View-space position of a pixel centre (x right, y up, z forward).
    Vec3 viewPosition(int x, int y, double z) const {
        const double a = sx[std::size_t(x)], b = sy[std::size_t(y)];
        return perspective ? Vec3{z * a, z * b, z} : Vec3{a, b, z};
    }
    // The quantity that is affine in image coordinates on a plane.
    double affine(double z) const { return perspective ? 1.0 / z : z; }
    Vec3 toWorld(const Vec3& v) const { return right * v.x + up * v.y + forward * v.z; }
};

// Everything one reconstruction needs besides the pixel.
struct Job {
    const float* depth;
    int width, height;
    const PlaneOffsets* plane;
    NormalMethod method;
    NormalOutputs out;
};

// The reference: pixel (x, y), any position in the image.
void normalAt(const Job& job, int x, int y);

// Pixels [x0, x1) of row y, 2 <= x0 <= x1 <= width - 2, computed several at a
// time with the best SIMD instructions the CPU has. `affine[k]` is
// PlaneOffsets::affine of every depth of row y - 2 + k (nullptr for rows
// outside the image); it is read only by the Extrapolated method. Returns the
// first pixel it did not compute (the rest of the span, shorter than a
// vector, is left to normalAt).
int normalsSpan(const Job& job, int y, int x0, int x1, const double* const affine[5]);

}  // namespace darkroom::normals
