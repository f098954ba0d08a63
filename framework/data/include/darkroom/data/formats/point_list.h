#pragma once
// Point lists: spheres kept as data rather than ray traced, so a pipeline can
// draw them post hoc (the Spheres node) with any radius and colour. A capture
// stores one beside each database entry as a small CSV (docs/capture.md);
// point clouds from VTK and PLY files read the same way.
//
// CSV form: a header naming the columns, then one point per row, numbers only:
//   x,y,z,radius,value
//   0.25,-0.5,0.125,0.02,1.07
// x, y, z are required (world units); `radius` is optional; every other column
// is a per-point field. Column names are matched exactly; empty cells and
// NaN are "no data" (a point without a finite position is skipped).
#include <darkroom/export.h>
#include <darkroom/math.h>
#include <darkroom/scene.h>

#include <string>
#include <vector>

namespace darkroom {

struct PointList {
    std::vector<Vec3> centers;
    std::vector<float> radii;          // one per point; NaN where none was given; empty = no radius column
    std::vector<ScalarField> fields;   // per point, in column order
    std::vector<std::string> warnings; // e.g. points skipped for a non-finite position
    std::size_t size() const { return centers.size(); }
};

// Reads a point list .csv as above. Throws darkroom::Error naming file:line
// and what was expected. (darkroom/scene/point_list.h reads mesh files too.)
DARKROOM_API PointList readPointListCsv(const std::string& path);

// The CSV text of the spheres of `object` (a points object: each vertex a
// sphere): x, y, z, radius and its point fields, numbers in shortest
// round-trip form. Cell fields of a points object are per point too.
DARKROOM_API std::string pointListCsv(const SceneObject& object);

}  // namespace darkroom
