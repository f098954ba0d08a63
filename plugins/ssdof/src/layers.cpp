#include "layers.h"

#include <algorithm>

namespace darkroom::ssdof {

void computeNearReach(WorkImage& w) {
    w.tilesX = (w.width + kTile - 1) / kTile;
    const int tilesY = (w.height + kTile - 1) / kTile;
    std::vector<float> own(std::size_t(w.tilesX) * std::size_t(tilesY), 0.0f);
    float largest = 0.0f;
    for (int y = 0; y < w.height; ++y)
        for (int x = 0; x < w.width; ++x) {
            const float s = w.coc[w.index(x, y)];
            if (s > -kInFocus) continue;
            float& t = own[std::size_t(y / kTile) * std::size_t(w.tilesX) + std::size_t(x / kTile)];
            t = std::max(t, -s);
            largest = std::max(largest, -s);
        }
    // A near pixel reaches at most |s| + 1 pixels, so tiles farther than that
    // (in whole tiles) cannot see it.
    const int k = int(std::ceil((largest + 1.0f) / float(kTile)));
    w.nearReach.assign(own.size(), 0.0f);
    for (int ty = 0; ty < tilesY; ++ty)
        for (int tx = 0; tx < w.tilesX; ++tx) {
            float m = 0.0f;
            for (int y = std::max(0, ty - k); y <= std::min(tilesY - 1, ty + k); ++y)
                for (int x = std::max(0, tx - k); x <= std::min(w.tilesX - 1, tx + k); ++x)
                    m = std::max(m, own[std::size_t(y) * std::size_t(w.tilesX) + std::size_t(x)]);
            w.nearReach[std::size_t(ty) * std::size_t(w.tilesX) + std::size_t(tx)] = m;
        }
}

}  // namespace darkroom::ssdof
