#pragma once
#include <darkroom/export.h>
#include <darkroom/math.h>

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace darkroom {

// How an object is drawn. Lines and points are ray traced as native round
// curves and spheres, never tessellated.
enum class Representation : std::uint8_t { Surface, Lines, Points };

DARKROOM_API const char* toString(Representation r);

struct ScalarField {
    enum class Association : std::uint8_t { Point, Cell };
    std::string name;
    Association association = Association::Point;
    // One value per vertex (Point) or per cell (Cell); NaN = no data.
    std::vector<float> values;
};

// One object of a scene, laid out so a capture backend can share the arrays
// with the ray tracer instead of copying them.
struct SceneObject {
    std::string name;
    Representation representation = Representation::Surface;
    // x, y, z, radius per vertex (16 bytes, the layout Embree shares for
    // triangles, round curves and sphere points alike). Radius is unused for surfaces.
    std::vector<float> vertices;
    // Surface: 3 vertex indices per triangle. Lines: one index per segment,
    // the segment joining vertex i and i+1. Points: empty (each vertex is a sphere).
    std::vector<std::uint32_t> indices;
    // Optional primitive -> cell map for cell data (e.g. a polyline's segments
    // all belong to one cell). Empty means primitive i is cell i.
    std::vector<std::uint32_t> primitiveCell;
    std::vector<ScalarField> fields;

    std::size_t vertexCount() const { return vertices.size() / 4; }
    DARKROOM_API std::size_t primitiveCount() const;
    const ScalarField* field(const std::string& n) const {
        for (const auto& f : fields)
            if (f.name == n) return &f;
        return nullptr;
    }
};

struct Bounds {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
            -std::numeric_limits<double>::infinity()};
    bool empty() const { return !(lo.x <= hi.x); }
    Vec3 center() const { return (lo + hi) * 0.5; }
    double radius() const { return empty() ? 0.0 : length(hi - lo) * 0.5; }
};

struct Scene {
    std::vector<SceneObject> objects;
    // Includes point and line radii.
    DARKROOM_API Bounds bounds() const;
};

}  // namespace darkroom
