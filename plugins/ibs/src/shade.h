#pragma once
// IBS's colour: the headlight term and the "over" of the outline colour, per
// pixel, in double precision.
#include <darkroom/camera.h>
#include <darkroom/context.h>
#include <darkroom/value.h>

#include <vector>

namespace darkroom::passes {

struct ShadeJob {
    int width = 0, height = 0;
    const float* rgb[3] = {nullptr, nullptr, nullptr};
    const float* alpha = nullptr;  // nullptr: opaque, no alpha written
    const float* silhouette = nullptr;
    // Lighting (nullptr: off): unit normals, world space (captured) or view
    // space (reconstructed), and the basis that takes world to view space.
    const float* normal[3] = {nullptr, nullptr, nullptr};
    bool worldNormals = false;
    Vec3 right, up, forward;
    bool perspective = true;
    std::vector<double> sx, sy;  // Camera::planeOffsets of the pixel centres
    double ambient = 0.2, luminance = 1.0;
    double strength = 1.0;
    Color color;
    float* out[3] = {nullptr, nullptr, nullptr};
    float* outAlpha = nullptr;

    bool lighting() const { return normal[0] != nullptr; }
    // Fills sx, sy for `camera` (with the image's size).
    void setView(const Camera& camera);
};

// Pixel (x, y), anywhere in the image.
void shadeAt(const ShadeJob& job, int x, int y);
// Pixels [0, width) of row y with the best SIMD instructions of the CPU;
// returns the first pixel not done (rows shorter than a vector: 0).
int shadeRow(const ShadeJob& job, int y);

// The whole image, rows in parallel.
void shade(Context& ctx, const ShadeJob& job);

}  // namespace darkroom::passes
