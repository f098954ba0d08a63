#include "ibs.h"

#include "shade.h"
#include "silhouette.h"

#include <darkroom/error.h>
#include <darkroom/view_geometry.h>

#include <algorithm>
#include <cmath>
#include <memory>

namespace darkroom {

void Ibs::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const float* depth = requireDepth(*in);
    const int w = in->width(), h = in->height();

    passes::SilhouetteOptions so;
    so.width = ctx.get(width_);
    so.depthThreshold = ctx.get(depthThreshold_);
    so.nearSide = ctx.get(side_) == Side::Near;
    if (!(so.width >= 0) || !(so.depthThreshold >= 0))
        throw Error("width and depthThreshold must be non-negative numbers");
    const std::uint32_t* ids = ctx.get(objectIds_) ? in->hostUInt("objectId") : nullptr;
    const double strength = std::clamp(ctx.get(strength_), 0.0, 1.0);
    const Color color = ctx.get(color_);
    const bool lighting = ctx.get(lighting_);
    const double luminance = ctx.get(luminance_);
    const double ambient = std::clamp(ctx.get(ambient_), 0.0, 1.0);

    const float* rgbIn[3] = {in->hostFloat("R"), in->hostFloat("G"), in->hostFloat("B")};
    const bool colour = rgbIn[0] && rgbIn[1] && rgbIn[2];
    const float* alphaIn = in->hostFloat("A");
    std::vector<ChannelDesc> fresh{"Silhouette"};
    if (colour) fresh.insert(fresh.end(), {"R", "G", "B"});
    if (colour && alphaIn) fresh.push_back("A");

    // Every fresh plane is written below.
    auto out = ctx.derive(in, fresh, Fill::None);
    float* outline = out->writeFloat("Silhouette");
    passes::silhouette(ctx, depth, ids, w, h, so, outline);
    if (colour) {
        passes::ShadeJob job;
        job.width = w;
        job.height = h;
        std::copy(rgbIn, rgbIn + 3, job.rgb);
        job.alpha = alphaIn;
        job.silhouette = outline;
        job.ambient = ambient;
        job.luminance = luminance;
        job.strength = strength;
        job.color = color;
        for (int k = 0; k < 3; ++k) job.out[k] = out->writeFloat(std::string(1, "RGB"[k]));
        job.outAlpha = alphaIn ? out->writeFloat("A") : nullptr;
        std::unique_ptr<float[]> reconstructed[3];
        if (lighting) {
            const Camera camera = camera_.get(ctx, *in, depth);
            job.setView(camera);
            const float* world[3] = {in->hostFloat("N.x"), in->hostFloat("N.y"), in->hostFloat("N.z")};
            if (world[0] && world[1] && world[2]) {
                std::copy(world, world + 3, job.normal);  // captured normals are exact
                job.worldNormals = true;
            } else {
                NormalOutputs o;
                for (int k = 0; k < 3; ++k) {
                    reconstructed[k].reset(new float[in->pixelCount()]);
                    o.view[k] = reconstructed[k].get();
                    job.normal[k] = reconstructed[k].get();
                }
                reconstructNormals(ctx, depth, w, h, camera, NormalMethod::Extrapolated, o);
            }
        }
        passes::shade(ctx, job);
    }
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
