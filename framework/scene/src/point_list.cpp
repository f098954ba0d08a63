// Point lists from mesh files, and the dispatch by extension (see point_list.h).
#include <darkroom/error.h>
#include <darkroom/scene/mesh_readers.h>
#include <darkroom/scene/point_list.h>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>

namespace darkroom {

namespace {

std::string lowerExtension(const std::string& path) {
    std::string e = std::filesystem::path(path).extension().string();
    std::transform(e.begin(), e.end(), e.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return e;
}

PointList meshPoints(const std::string& path) {
    PointList p;
    const std::vector<SceneObject> parts = readMesh(path, &p.warnings);
    for (const SceneObject& o : parts) {
        const std::size_t base = p.centers.size();
        for (std::size_t v = 0; v < o.vertexCount(); ++v)
            p.centers.push_back({o.vertices[4 * v], o.vertices[4 * v + 1], o.vertices[4 * v + 2]});
        // Point fields by name across parts; missing in a part = NaN.
        for (const ScalarField& f : o.fields) {
            if (f.association != ScalarField::Association::Point) continue;
            auto it = std::find_if(p.fields.begin(), p.fields.end(), [&](const ScalarField& g) { return g.name == f.name; });
            if (it == p.fields.end()) {
                p.fields.push_back({f.name, ScalarField::Association::Point, {}});
                it = p.fields.end() - 1;
            }
            it->values.resize(base, std::numeric_limits<float>::quiet_NaN());
            it->values.insert(it->values.end(), f.values.begin(), f.values.end());
        }
        for (ScalarField& g : p.fields) g.values.resize(p.centers.size(), std::numeric_limits<float>::quiet_NaN());
    }
    return p;
}

}  // namespace

PointList readPointList(const std::string& path) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
        throw Error(fmt::format("point list {} does not exist or is not a file", path));
    return lowerExtension(path) == ".csv" ? readPointListCsv(path) : meshPoints(path);
}

PointList readNodePointList(Context& ctx, std::string spec, const std::function<const Row&()>& row,
                            std::string* resolved) {
    if (spec.empty())
        throw Error("no point list given; set 'points' to a CSV (x, y, z[, radius, line, fields]) or mesh file");
    if (hasRowPlaceholders(spec)) {
        const Row& r = row();
        if (r.empty()) throw Error("'points' (" + spec + ") has placeholders but 'row' is empty; connect CinemaReader's row");
        spec = fillRowPlaceholders(spec, r, "points");
    }
    const std::string path = ctx.resolveInputPath(spec);
    ctx.readsFile(path);
    if (resolved) *resolved = path;
    PointList list = readPointList(path);
    for (const auto& w : list.warnings) ctx.warn(w);
    return list;
}

}  // namespace darkroom
