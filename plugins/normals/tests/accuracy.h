#pragma once
// Angular error of reconstructed normals against the normals captured by the
// embree backend (true geometric normals), split into pixels next to a depth
// discontinuity ("edges") and the rest ("interior").
#include <darkroom/buffer.h>

#include <string>
#include <vector>

namespace darkroom::test {

struct AngleStats {
    std::size_t count = 0;
    double mean = 0, median = 0, p95 = 0;  // degrees
};

struct NormalAccuracy {
    AngleStats edges, interior;
};

// `truth` holds Z and the captured N.*; `reconstructed` holds N.*. A pixel is
// an edge pixel when one of its 8 neighbours is background or differs in depth
// by more than `relativeJump` of its own depth.
NormalAccuracy compareNormals(const Buffer& truth, const Buffer& reconstructed, double relativeJump = 0.02);

}  // namespace darkroom::test
