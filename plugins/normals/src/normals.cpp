#include "normals.h"

namespace darkroom {

void Normals::execute(Context& ctx) {
    const BufferPtr in = ctx.get(image_);
    const float* depth = requireDepth(*in);
    const Camera camera = camera_.get(ctx, *in, depth);
    const bool captured = in->hostFloat("N.x") && in->hostFloat("N.y") && in->hostFloat("N.z");
    const bool keep = captured && !ctx.get(replace_);

    std::vector<ChannelDesc> fresh{"Nv.x", "Nv.y", "Nv.z", "P.x", "P.y", "P.z"};
    if (!keep) fresh.insert(fresh.begin(), {"N.x", "N.y", "N.z"});
    // The reconstruction writes every pixel (NaN where there is no surface).
    auto out = ctx.derive(in, fresh, Fill::None);

    NormalOutputs dst;
    dst.viewZTowardsViewer = true;  // Nv is a normal map in the OpenGL convention
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        dst.view[k] = out->writeFloat(std::string("Nv.") + axes[k]);
        dst.position[k] = out->writeFloat(std::string("P.") + axes[k]);
        if (!keep) dst.world[k] = out->writeFloat(std::string("N.") + axes[k]);
    }
    reconstructNormals(ctx, depth, in->width(), in->height(), camera, ctx.get(method_), dst);
    if (keep) {
        // Captured normals are exact: derive Nv from them so N and Nv agree.
        const float* world[3] = {in->hostFloat("N.x"), in->hostFloat("N.y"), in->hostFloat("N.z")};
        worldToViewNormals(ctx, world, in->pixelCount(), camera, dst.view, true);
    }
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
