#pragma once
// Front-to-back compositing of translucent colour surfaces (issue 30): the
// one blend that ColorMapping (the layers of one buffer), Compositing (the
// layers of several buffers) and the editor's "composite" view share, so
// the three give the same colour for the same surfaces.
//
// Colour in the graph is straight (not premultiplied) alpha. Surfaces are
// blended in increasing depth:
//     C = sum_k a_k c_k prod_{j<k} (1 - a_j),   A = 1 - prod_k (1 - a_k)
// and the result is returned straight again, C / A.
#include <cmath>
#include <limits>

namespace darkroom::layers {

// One surface on a pixel's ray: depth and straight-alpha colour.
struct Surface {
    float z, r, g, b, a;
};

struct Blended {
    float r = 0, g = 0, b = 0, a = 0;  // straight alpha; all 0 when nothing contributed
    float z = std::numeric_limits<float>::infinity();  // the nearest contributing surface
    int contributing = 0;  // surfaces with finite depth and alpha > 0 that were reached
};

// Sorts s[0, n) by depth (insertion sort: n is a handful, and a stable sort
// keeps equal depths in the caller's order) and blends front to back.
// Surfaces with non-finite depth (missing layers, background) or alpha <= 0
// (or NaN) take no part. Blending stops at the first opaque surface, so
// nothing behind it (not even a NaN colour) changes the result, and one
// contributing surface comes back bit for bit as it went in.
inline Blended blendFrontToBack(Surface* s, int n) {
    for (int i = 1; i < n; ++i)
        for (int j = i; j > 0 && s[j].z < s[j - 1].z; --j) {
            const Surface t = s[j];
            s[j] = s[j - 1];
            s[j - 1] = t;
        }
    Blended out;
    float r = 0, g = 0, b = 0, transmit = 1;
    const Surface* only = nullptr;
    for (int k = 0; k < n && transmit > 0; ++k) {
        const Surface& x = s[k];
        if (!std::isfinite(x.z) || !(x.a > 0)) continue;
        const float a = x.a < 1 ? x.a : 1.0f;
        const float w = a * transmit;
        r += w * x.r;
        g += w * x.g;
        b += w * x.b;
        transmit *= 1.0f - a;
        if (out.contributing++ == 0) {
            out.z = x.z;
            only = &x;
        }
    }
    if (out.contributing == 0) return out;
    if (out.contributing == 1) {
        out.r = only->r, out.g = only->g, out.b = only->b, out.a = only->a;
        return out;
    }
    out.a = 1.0f - transmit;
    out.r = r / out.a, out.g = g / out.a, out.b = b / out.a;
    return out;
}

}  // namespace darkroom::layers
