#include "step_bounds.h"

#include "embree_scene.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace darkroom::insitu {

namespace {

void add(Bounds& b, const Vec3& lo, const Vec3& hi) {
    b.lo = {std::min(b.lo.x, lo.x), std::min(b.lo.y, lo.y), std::min(b.lo.z, lo.z)};
    b.hi = {std::max(b.hi.x, hi.x), std::max(b.hi.y, hi.y), std::max(b.hi.z, hi.z)};
}

}  // namespace

Bounds boundsOf(const std::vector<embree::ObjectView>& objects) {
    Bounds b;
    for (const auto& o : objects) {
        const bool round = o.representation != Representation::Surface;
        for (std::size_t i = 0; i < o.vertexCount; ++i) {
            const float* v = o.vertex(i);
            if (!std::isfinite(v[0]) || !std::isfinite(v[1]) || !std::isfinite(v[2])) continue;
            const double r = round && std::isfinite(v[3]) ? std::abs(double(v[3])) : 0.0;
            add(b, {v[0] - r, v[1] - r, v[2] - r}, {v[0] + r, v[1] + r, v[2] + r});
        }
    }
    return b;
}

Bounds agreeBounds(ProcessGroup& ranks, const Bounds& mine) {
    if (ranks.size() == 1) return mine;
    // Hexadecimal floating point: exact, whatever the locale.
    char text[256];
    std::snprintf(text, sizeof text, "%a %a %a %a %a %a", mine.lo.x, mine.lo.y, mine.lo.z, mine.hi.x, mine.hi.y,
                  mine.hi.z);
    Bounds all;
    for (const std::string& s : ranks.allGather(text)) {
        double v[6];
        const char* p = s.c_str();
        for (double& x : v) {
            char* end = nullptr;
            x = std::strtod(p, &end);
            p = end;
        }
        add(all, {v[0], v[1], v[2]}, {v[3], v[4], v[5]});
    }
    return all;
}

}  // namespace darkroom::insitu
