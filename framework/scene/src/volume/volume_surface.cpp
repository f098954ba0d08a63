// volumeSurface(): one representation of a volume as a SceneObject.
#include "volume_polymesh.h"

#include <darkroom/error.h>

#include <cmath>
#include <limits>

namespace darkroom {

namespace volume {

void takePoints(const VolumeMesh& v, const PointMap& points, mesh::PolyMesh& out) {
    const auto& src = points.source();
    out.points.resize(src.size() * 3);
    for (std::size_t i = 0; i < src.size(); ++i) {
        const Vec3 p = v.point(src[i]);
        out.points[3 * i] = float(p.x), out.points[3 * i + 1] = float(p.y), out.points[3 * i + 2] = float(p.z);
    }
    for (const auto& a : v.pointData) {
        mesh::DataArray d{a.name, a.components, std::vector<float>(src.size() * std::size_t(a.components))};
        const std::size_t nc = std::size_t(a.components);
        for (std::size_t i = 0; i < src.size(); ++i)
            for (std::size_t c = 0; c < nc; ++c) d.values[i * nc + c] = a.values[std::size_t(src[i]) * nc + c];
        out.pointData.push_back(std::move(d));
    }
}

}  // namespace volume

namespace {

std::string arrayList(const std::vector<VolumeArray>& arrays) {
    std::string s;
    for (const auto& a : arrays) s += (s.empty() ? "" : ", ") + a.name;
    return s.empty() ? std::string("none") : s;
}

}  // namespace

SceneObject volumeSurface(const VolumeMesh& v, const VolumeRepresentation& r, const std::string& name) {
    if (v.pointCount() >= 0xffffffffull || v.cellCount() >= 0xffffffffull)
        throw Error(v.source + ": more than 2^32 points or cells; volumes are indexed with 32 bits");
    mesh::PolyMesh out;
    out.source = v.source;
    out.cellCount = v.cellCount();
    for (const auto& a : v.cellData) out.cellData.push_back({a.name, a.components, a.values});
    if (r.kind == VolumeRepresentation::Kind::Boundary) {
        volume::PointMap points(v.pointCount());
        volume::buildBoundary(v, out, points);
        volume::takePoints(v, points, out);
        if (out.polygons.size() == 0)
            throw Error(v.source + ": no boundary surface: the file has no 3D or 2D cells");
    } else {
        if (r.kind == VolumeRepresentation::Kind::Isosurface) {
            const VolumeArray* f = nullptr;
            for (const auto& a : v.pointData)
                if (a.name == r.contourBy) f = &a;
            if (!f)
                throw Error(v.source + ": no point field '" + r.contourBy + "' to contour (point fields: " +
                            arrayList(v.pointData) + "; cell fields cannot be contoured)");
            if (f->components != 1)
                throw Error(v.source + ": point field '" + r.contourBy + "' has " + std::to_string(f->components) +
                            " components; isosurfaces need a scalar field");
        }
        volume::buildContour(v, r, out);
        if (out.polygons.size() == 0) {
            std::string what = "the volume's cells";
            if (r.kind == VolumeRepresentation::Kind::Isosurface) {
                float lo = std::numeric_limits<float>::infinity(), hi = -lo;
                for (const auto& a : v.pointData)
                    if (a.name == r.contourBy)
                        for (float x : a.values)
                            if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
                what = "'" + r.contourBy + "', which ranges from " + std::to_string(lo) + " to " + std::to_string(hi);
            }
            throw Error(v.source + ": the " + toString(r.kind) + " is empty: no " +
                        (r.kind == VolumeRepresentation::Kind::Slice ? "plane cuts " : "isovalue lies within ") + what);
        }
    }
    auto objects = mesh::buildSceneObjects(out, name);
    if (objects.size() != 1) throw Error(v.source + ": internal: a volume representation gave several parts");
    return std::move(objects.front());
}

}  // namespace darkroom
