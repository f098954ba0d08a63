#include "normals.h"

#include "../lib/depth_normals.h"
#include "../lib/pass_through.h"

namespace darkroom {

PortList Normals::ports() const {
    PortList p;
    p.imageIn("image", "Depth Z (planar view depth, +inf background) with its camera in the metadata",
              {"Z"});
    p.enumIn("method", passes::normalMethodNames(), "extrapolated",
             "central: central differences (wrong at depth edges); nearest: per axis the one-sided "
             "difference towards the closer depth; extrapolated: per axis the side whose two "
             "neighbours extrapolate best to the centre, central where both agree (most accurate)");
    p.boolIn("replace", false,
             "When the input already has N.x/N.y/N.z (e.g. captured normals), overwrite them with "
             "the reconstruction; when false they are kept and Nv is derived from them");
    p.imageOut("image",
               "All input channels plus world normals N.x/N.y/N.z, view-space normals Nv.x/Nv.y/Nv.z "
               "(x right, y up, z towards the viewer) and world positions P.x/P.y/P.z; NaN on "
               "background",
               {"N.x", "N.y", "N.z", "Nv.x", "Nv.y", "Nv.z", "P.x", "P.y", "P.z"});
    return p;
}

void Normals::execute(Context& ctx) {
    const BufferPtr in = ctx.requireImage("image");
    const std::string node = "Normals '" + ctx.nodeName() + "'";
    const float* depth = in->requireFloat("Z");
    const Camera camera = passes::requireCamera(*in, node + ": input 'image'");
    const passes::NormalMethod method = passes::parseNormalMethod(ctx.getString("method"));
    const bool captured = in->hostFloat("N.x") && in->hostFloat("N.y") && in->hostFloat("N.z");
    const bool keep = captured && !ctx.getBool("replace");

    std::vector<std::string> added{"Nv.x", "Nv.y", "Nv.z", "P.x", "P.y", "P.z"};
    if (!keep) added.insert(added.begin(), {"N.x", "N.y", "N.z"});
    auto out = passes::allocatePassThrough(ctx, *in, added);
    if (ctx.cancelled()) return;

    passes::NormalOutputs dst;
    const char* axes[3] = {"x", "y", "z"};
    for (int k = 0; k < 3; ++k) {
        dst.view[k] = out->requireFloat(std::string("Nv.") + axes[k]);
        dst.position[k] = out->requireFloat(std::string("P.") + axes[k]);
        if (!keep) dst.world[k] = out->requireFloat(std::string("N.") + axes[k]);
    }
    passes::reconstructNormals(ctx, depth, in->width(), in->height(), camera, method, dst);
    if (keep) {
        // Captured normals are exact: derive Nv from them so N and Nv agree.
        const float* world[3] = {in->hostFloat("N.x"), in->hostFloat("N.y"), in->hostFloat("N.z")};
        passes::worldToViewNormals(ctx, world, in->pixelCount(), camera, dst.view);
    }
    if (ctx.cancelled()) return;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
