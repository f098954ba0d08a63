#pragma once
// The synthetic capture shared by the writer tests and the kill-then-resume
// child process: 20 entries on a phi/theta grid with negative and fractional
// angles, each a small G-buffer (depth, a scalar, an id) with its camera.
#include <darkroom/buffer.h>
#include <darkroom/data/cinema/writer.h>

#include <cmath>
#include <limits>
#include <vector>

namespace darkroom::test {

inline std::vector<CinemaParameters> gridEntries() {
    std::vector<CinemaParameters> out;
    for (double phi : {-45.0, -22.5, 0.0, 22.5, 45.0})
        for (double theta : {-30.0, 0.0, 30.0, 60.0}) out.push_back({{"phi", phi}, {"theta", theta}});
    return out;
}

// Deterministic pixels per entry; `size` lets the kill test make writes slow
// enough to be interrupted in the middle.
inline std::shared_ptr<WritableBuffer> gridImage(const CinemaParameters& p, int size = 32) {
    const double phi = p.at("phi").number(), theta = p.at("theta").number();
    auto b = makeCpuBuffer(size, size * 3 / 4,
                           {{"Z", ChannelType::Float32},
                            {"Elevation", ChannelType::Float32},
                            {"ObjectId", ChannelType::UInt32}});
    float* z = b->writeFloat("Z");
    float* e = b->writeFloat("Elevation");
    std::uint32_t* id = b->writeUInt("ObjectId");
    for (int y = 0; y < b->height(); ++y)
        for (int x = 0; x < b->width(); ++x) {
            const std::size_t i = std::size_t(y) * b->width() + x;
            const bool background = (x + y) % 7 == 0;
            z[i] = background ? std::numeric_limits<float>::infinity()
                              : float(2.0 + 0.01 * x + 0.001 * phi);
            e[i] = background ? std::numeric_limits<float>::quiet_NaN()
                              : float(std::sin(0.1 * x + phi) * std::cos(0.1 * y + theta));
            id[i] = background ? 0u : std::uint32_t(1 + (x / 8) + 10 * (y / 8));
        }
    Camera cam;
    cam.position = {std::cos(phi) * 5, std::sin(theta) * 5, 1};
    cam.forward = {-cam.position.x, -cam.position.y, -cam.position.z};
    cam.fovYDegrees = 35;
    cam.width = b->width();
    cam.height = b->height();
    b->metadata().camera = cam;
    b->metadata().attributes["units.Z"] = "m";
    return b;
}

}  // namespace darkroom::test
