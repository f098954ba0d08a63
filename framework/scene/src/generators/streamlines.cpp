// `streamlines`: RK4 streamlines of the ABC flow in [-1,1]^3, one polyline
// per seed, clipped where they leave the cube.
#include "builtin_generators.h"
#include <darkroom/scene/hash_random.h>

#include <darkroom/scene/generators.h>
#include <darkroom/limits.h>

#include <tbb/parallel_for.h>

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace darkroom::generators {
namespace {

struct Sample {
    Vec3 p;
    double t;
};

bool insideCube(const Vec3& p) { return std::abs(p.x) <= 1 && std::abs(p.y) <= 1 && std::abs(p.z) <= 1; }

// Largest s in [0, 1] with a + s (b - a) still in the cube (a is inside).
double exitFraction(const Vec3& a, const Vec3& b) {
    double s = 1;
    for (int axis = 0; axis < 3; ++axis) {
        const double d = b[axis] - a[axis];
        if (d > 0 && b[axis] > 1) s = std::min(s, (1 - a[axis]) / d);
        if (d < 0 && b[axis] < -1) s = std::min(s, (-1 - a[axis]) / d);
    }
    return std::clamp(s, 0.0, 1.0);
}

std::vector<Sample> trace(const StreamlineOptions& o, const Vec3& seed, double h) {
    auto v = [&](const Vec3& p) { return abcVelocity(p, o.a, o.b, o.c); };
    std::vector<Sample> out;
    Vec3 p = seed;
    double t = 0;
    for (int s = 0; s < o.steps; ++s) {
        const Vec3 k1 = v(p);
        if (length(k1) < 1e-9) break;  // stagnation point: the line ends here
        const Vec3 k2 = v(p + k1 * (h / 2));
        const Vec3 k3 = v(p + k2 * (h / 2));
        const Vec3 k4 = v(p + k3 * h);
        const Vec3 next = p + (k1 + k2 * 2 + k3 * 2 + k4) * (h / 6);
        if (!insideCube(next)) {
            const double f = exitFraction(p, next);
            if (f > 1e-9) out.push_back({p + (next - p) * f, t + h * f});
            break;
        }
        p = next;
        t += h;
        out.push_back({p, t});
    }
    return out;
}

}  // namespace

StreamlineOptions readStreamlineOptions(GeneratorParams& p) {
    StreamlineOptions o;
    o.count = p.integer("count", o.count, 0, 1000000);
    o.step = p.number("step", o.step, 1e-4, 1.0);
    if (p.has("steps") && p.has("length"))
        p.fail("steps", "cannot be combined with 'length' (give the integration time or the step count)");
    o.steps = p.integer("steps", o.steps, 1, 1000000);
    if (p.has("length")) {
        const double steps = std::ceil(p.number("length", 10, 1e-3, 1e5) / o.step - 1e-9);
        if (steps > 1e6) p.fail("length", fmt::format("gives {} steps of {}, more than 1000000", steps, o.step));
        o.steps = int(steps);
    }
    o.radius = p.number("radius", o.radius, 0.0, 1.0);
    o.a = p.number("A", o.a, -100, 100);
    o.b = p.number("B", o.b, -100, 100);
    o.c = p.number("C", o.c, -100, 100);
    o.direction = p.choice("direction", o.direction, {"forward", "backward", "both"});
    o.seed = std::uint64_t(p.integer("seed", int(o.seed), 0, 2147483647));
    p.finish();
    // Bounded before a line is traced: a million lines of a million steps
    // would take 10^12 RK4 steps and as many vertices (24 bytes each: x, y,
    // z, radius, time, segment index), hours and terabytes.
    const double vertices = double(o.count) * (double(o.steps) * (o.direction == "both" ? 2.0 : 1.0) + 1.0);
    const double bytes = vertices * 24.0;
    const double allowed = double(limit(Limit::DecodedBytes));
    if (bytes > allowed)
        p.fail(p.has("steps") ? "steps" : "count",
               fmt::format("makes up to {:.0f} vertices ({} lines of up to {} steps, {:.3g} bytes), more than "
                           "{} allows ({} bytes): lower 'count' or 'steps', or raise the limit",
                           vertices, o.count, o.steps, bytes, limitOption(Limit::DecodedBytes), limit(Limit::DecodedBytes)));
    return o;
}

SceneObject buildStreamlines(const StreamlineOptions& o) {
    // Each line is traced independently (in parallel), then concatenated in
    // seed order, so the output does not depend on the thread count.
    std::vector<std::vector<Sample>> lines(std::size_t(std::max(o.count, 0)));
    tbb::parallel_for(0, o.count, [&](int i) {
        Vec3 seed;
        for (int axis = 0; axis < 3; ++axis) {
            const double u = 0.95 * (2 * hashUniform(o.seed, std::uint64_t(i), std::uint64_t(axis)) - 1);
            (axis == 0 ? seed.x : axis == 1 ? seed.y : seed.z) = u;
        }
        std::vector<Sample> line;
        if (o.direction != "forward") {
            line = trace(o, seed, -o.step);
            std::reverse(line.begin(), line.end());  // time must increase along the polyline
        }
        line.push_back({seed, 0});
        if (o.direction != "backward") {
            const auto forward = trace(o, seed, o.step);
            line.insert(line.end(), forward.begin(), forward.end());
        }
        lines[std::size_t(i)] = std::move(line);
    });

    SceneObject obj;
    obj.name = "streamlines";
    obj.representation = Representation::Lines;
    ScalarField time{"time", ScalarField::Association::Point, {}};
    ScalarField speed{"speed", ScalarField::Association::Point, {}};
    ScalarField lineId{"line", ScalarField::Association::Cell, {}};
    for (const auto& line : lines) {
        if (line.size() < 2) continue;  // a seed on a stagnation point makes no line
        const auto first = std::uint32_t(obj.vertexCount());
        for (std::size_t k = 0; k < line.size(); ++k) {
            appendVertex(obj, line[k].p, o.radius);
            time.values.push_back(float(line[k].t));
            speed.values.push_back(float(length(abcVelocity(line[k].p, o.a, o.b, o.c))));
            // Segment k joins vertices k and k+1; none joins two lines.
            if (k + 1 < line.size()) obj.indices.push_back(first + std::uint32_t(k));
        }
        // One cell per line: colouring by `line` tells the lines apart.
        obj.primitiveCell.insert(obj.primitiveCell.end(), line.size() - 1, std::uint32_t(lineId.values.size()));
        lineId.values.push_back(float(lineId.values.size()));
    }
    obj.fields = {std::move(time), std::move(speed), std::move(lineId)};
    return obj;
}

}  // namespace darkroom::generators
