#pragma once
// Decodes an MP4 back with FFmpeg (libavformat/libavcodec) for the tests:
// what a player would see.
#include <string>
#include <vector>

namespace darkroom::test {

struct DecodedMovie {
    std::string container, codec;
    int width = 0, height = 0;
    double frameRate = 0;            // the stream's average frame rate
    std::vector<double> meanLuma;    // per decoded frame, the mean of Y (8-bit code values)
    std::vector<double> lumaAt;      // per frame, Y at the pixel (x, y) asked for
    int frames() const { return int(meanLuma.size()); }
};

// Throws std::runtime_error when the file cannot be decoded.
DecodedMovie decodeMovie(const std::string& path, int x = 0, int y = 0);

}  // namespace darkroom::test
