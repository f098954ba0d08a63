// `maxima`: spheres at the local maxima of demoField(), found on a grid and
// refined by Newton's method on the analytic gradient.
#include "builtin_generators.h"

#include <darkroom/scene/generators.h>

#include <algorithm>
#include <cmath>

namespace darkroom::generators {
namespace {

// Solves H x = g for a symmetric 3x3 H (Cramer's rule); false if singular.
bool solve3(const Vec3 h[3], const Vec3& g, Vec3& x) {
    const double det = dot(h[0], cross(h[1], h[2]));
    if (std::abs(det) < 1e-300) return false;
    // Columns of H are h[0..2] (H is symmetric, so rows too).
    x = Vec3{dot(g, cross(h[1], h[2])), dot(h[0], cross(g, h[2])), dot(h[0], cross(h[1], g))} * (1.0 / det);
    return true;
}

// Hessian by central differences of the analytic gradient: accurate to
// ~1e-8, enough for Newton's quadratic convergence near the maximum.
void hessian(const Vec3& p, Vec3 h[3]) {
    const double e = 1e-5;
    const Vec3 axes[3] = {{e, 0, 0}, {0, e, 0}, {0, 0, e}};
    for (int i = 0; i < 3; ++i)
        h[i] = (demoFieldGradient(p + axes[i]) - demoFieldGradient(p - axes[i])) * (0.5 / e);
}

bool negativeDefinite(const Vec3 h[3]) {
    const double m1 = h[0].x, m2 = h[0].x * h[1].y - h[0].y * h[1].x, m3 = dot(h[0], cross(h[1], h[2]));
    return m1 < 0 && m2 > 0 && m3 < 0;
}

// Newton where the Hessian is negative definite, otherwise a backtracking
// gradient step; every accepted step raises f, so it cannot settle on a saddle
// it started above.
Vec3 refine(Vec3 p) {
    for (int it = 0; it < 200; ++it) {
        const Vec3 g = demoFieldGradient(p);
        if (length(g) < 1e-12) break;
        Vec3 h[3];
        hessian(p, h);
        Vec3 step;
        const double f = demoField(p);
        if (negativeDefinite(h) && solve3(h, g, step)) {
            const Vec3 q = p - step;
            if (demoField(q) >= f) {
                if (length(step) < 1e-14) break;
                p = q;
                continue;
            }
        }
        double s = 0.01;
        while (s > 1e-12 && demoField(p + g * s) <= f) s *= 0.5;
        if (s <= 1e-12) break;
        p = p + g * s;
    }
    return p;
}

}  // namespace

MaximaOptions readMaximaOptions(GeneratorParams& p) {
    MaximaOptions o;
    o.radius = p.number("radius", o.radius, 0.0, 1.0);
    o.resolution = p.integer("resolution", o.resolution, 3, 256);
    o.minValue = p.number("min value", o.minValue, 0.0, 10.0);
    p.finish();
    return o;
}

std::vector<Vec3> demoFieldMaxima(int resolution, double minValue) {
    const int n = resolution;
    const double h = 2.0 / (n - 1);
    std::vector<double> v(std::size_t(n) * n * n);
    auto at = [&](int i, int j, int k) -> double& { return v[(std::size_t(k) * n + j) * n + i]; };
    for (int k = 0; k < n; ++k)
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) at(i, j, k) = demoField({-1 + i * h, -1 + j * h, -1 + k * h});
    std::vector<Vec3> found;
    for (int k = 1; k + 1 < n; ++k)
        for (int j = 1; j + 1 < n; ++j)
            for (int i = 1; i + 1 < n; ++i) {
                const double c = at(i, j, k);
                if (c < minValue) continue;
                bool peak = true;
                for (int d = 0; d < 27 && peak; ++d)
                    if (d != 13) peak = c > at(i + d % 3 - 1, j + d / 3 % 3 - 1, k + d / 9 - 1);
                if (!peak) continue;
                const Vec3 m = refine({-1 + i * h, -1 + j * h, -1 + k * h});
                const bool known = std::any_of(found.begin(), found.end(),
                                               [&](const Vec3& q) { return length(q - m) < 1e-5; });
                if (!known && demoField(m) >= minValue) found.push_back(m);
            }
    // Highest first: a stable order that also reads well in a table.
    std::sort(found.begin(), found.end(), [](const Vec3& a, const Vec3& b) { return demoField(a) > demoField(b); });
    return found;
}

SceneObject buildMaxima(const MaximaOptions& o) {
    SceneObject obj;
    obj.name = "maxima";
    obj.representation = Representation::Points;
    ScalarField value{"value", ScalarField::Association::Point, {}};
    for (const Vec3& m : demoFieldMaxima(o.resolution, o.minValue)) {
        appendVertex(obj, m, o.radius);
        value.values.push_back(float(demoField(m)));
    }
    obj.fields = {std::move(value)};
    return obj;
}

}  // namespace darkroom::generators
