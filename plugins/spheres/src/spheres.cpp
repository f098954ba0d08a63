#include "spheres.h"

#include "sphere_raster.h"

#include <darkroom/error.h>
#include <darkroom/data/cinema/row.h>
#include <darkroom/scene/point_list.h>
#include <darkroom/view_geometry.h>

#include <cmath>
#include <limits>

namespace darkroom {

namespace {

const std::uint32_t kNoPoint = 0xffffffffu;

}  // namespace

void Spheres::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const Camera camera = requireCamera(*in, "input 'image'");

    std::string path;
    const PointList list =
        readNodePointList(ctx, ctx.getString(points_.name()), [&]() -> const Row& { return ctx.get(row_); }, &path);

    const double fallback = ctx.get(radius_), scale = ctx.get(radiusScale_);
    std::vector<spheres::Sphere> balls(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        const double r = list.radii.empty() || std::isnan(list.radii[i]) ? fallback : double(list.radii[i]);
        balls[i] = {list.centers[i], r * scale};
    }
    const spheres::Hits hits = spheres::castSpheres(ctx, camera, balls);

    std::vector<ChannelDesc> channels{"Z", "N.x", "N.y", "N.z"};
    for (const ScalarField& f : list.fields) {
        for (const auto& c : channels)
            if (c.name == f.name)
                throw Error(path + ": the field '" + f.name + "' has the name of a G-buffer channel; rename the column");
        channels.emplace_back(f.name);
    }
    channels.emplace_back("pointId", ChannelType::UInt32);
    auto out = ctx.allocate(in->width(), in->height(), channels, Fill::None);
    out->metadata().camera = camera;
    const std::size_t n = in->pixelCount();
    std::copy(hits.depth.begin(), hits.depth.end(), out->writeFloat("Z"));
    const char* normalNames[3] = {"N.x", "N.y", "N.z"};
    for (int c = 0; c < 3; ++c) std::copy(hits.normal[c].begin(), hits.normal[c].end(), out->writeFloat(normalNames[c]));
    for (const ScalarField& f : list.fields) {
        float* d = out->writeFloat(f.name);
        for (std::size_t p = 0; p < n; ++p)
            d[p] = hits.index[p] < 0 ? std::numeric_limits<float>::quiet_NaN() : f.values[std::size_t(hits.index[p])];
    }
    std::uint32_t* ids = out->writeUInt("pointId");
    for (std::size_t p = 0; p < n; ++p) ids[p] = hits.index[p] < 0 ? kNoPoint : std::uint32_t(hits.index[p]);
    out->metadata().attributes["source"] = path;
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
