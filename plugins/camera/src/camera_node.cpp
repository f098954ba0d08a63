#include "camera_node.h"

#include "camera_from_view.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

namespace darkroom {

PortList CameraNode::ports() const {
    PortList p;
    p.imageIn("image", "Any image; Z is needed only to convert depth");
    p.enumIn("apply", {"always", "whenMissing"}, "always",
             "always: replace the image's camera; whenMissing: keep a camera the image already has");
    p.vec3In("position", Vec3{0, 0, 1}, "Camera position in world units (ParaView: CameraPosition)");
    p.vec3In("focalPoint", Vec3{0, 0, 0}, "Point the camera looks at (ParaView: CameraFocalPoint)");
    p.vec3In("viewUp", Vec3{0, 1, 0}, "Up direction of the view (ParaView: CameraViewUp)");
    p.boolIn("parallelProjection", false,
             "Orthographic view (ParaView: CameraParallelProjection); otherwise perspective");
    p.floatIn("viewAngle", 30.0, 1e-3, 179.999,
              "Perspective: full vertical field of view in degrees (ParaView: CameraViewAngle)");
    p.floatIn("parallelScale", 1.0, 1e-30, 1e30,
              "Orthographic: half the view height in world units (ParaView: CameraParallelScale)");
    p.enumIn("depth", {"distance", "normalised"}, "distance",
             "distance: Z already holds planar view depth, kept; normalised: Z holds depth normalised to [0, 1] "
             "between near and far (TTK's CinemaImaging), turned into near + Z (far - near)");
    p.floatIn("near", 0.0, 0.0, 1e30, "Near distance of the normalised depth (TTK: CamNearFar[0])");
    p.floatIn("far", 1.0, 0.0, 1e30, "Far distance of the normalised depth (TTK: CamNearFar[1])");
    p.imageOut("image", "The image with the camera set (every channel passes through; Z converted when asked)");
    return p;
}

void CameraNode::execute(Context& ctx) {
    const std::string who = "Camera '" + ctx.nodeName() + "'";
    const BufferPtr in = ctx.requireImage("image");
    const bool keepExisting = ctx.getString("apply") == "whenMissing" && in->metadata().camera.has_value();
    const bool normalised = ctx.getString("depth") == "normalised";
    if (keepExisting && !normalised) {
        ctx.setOutput("image", in);  // nothing to change
        return;
    }
    ParaViewCamera view;
    view.position = ctx.getVec3("position");
    view.focalPoint = ctx.getVec3("focalPoint");
    view.viewUp = ctx.getVec3("viewUp");
    view.parallelProjection = ctx.getBool("parallelProjection");
    view.viewAngle = ctx.getFloat("viewAngle");
    view.parallelScale = ctx.getFloat("parallelScale");
    const Camera camera = cameraFromParaView(view, in->width(), in->height(), who);

    const double nearValue = ctx.getFloat("near"), farValue = ctx.getFloat("far");
    const float* z = nullptr;
    if (normalised) {
        if (!(farValue > nearValue))
            throw Error(who + ": far (" + std::to_string(farValue) + ") must be greater than near (" +
                        std::to_string(nearValue) + ") to convert normalised depth");
        z = in->hostFloat("Z");
        if (!z) {
            std::string names;
            for (const auto& n : in->channelNames()) names += (names.empty() ? "" : ", ") + n;
            throw Error(who + ": depth 'normalised' needs a float channel Z; the image has " +
                        (names.empty() ? std::string("no channels") : names));
        }
        // Converting twice (or distances) would be silently wrong: refuse values outside [0, 1].
        for (std::size_t i = 0; i < in->pixelCount(); ++i)
            if (std::isfinite(z[i]) && (z[i] < 0.f || z[i] > 1.f)) {
                std::ostringstream s;
                s << who << ": depth 'normalised' expects Z in [0, 1] (or +inf for background), but pixel ("
                  << i % std::size_t(in->width()) << ", " << i / std::size_t(in->width()) << ") holds " << z[i]
                  << "; is Z already a distance? Use depth 'distance'";
                throw Error(s.str());
            }
    }

    auto out = ctx.allocate(in->width(), in->height(), in->channels());
    out->metadata() = in->metadata();
    if (!keepExisting) out->metadata().camera = camera;
    const std::size_t n = in->pixelCount();
    for (const auto& ch : in->channels()) {
        if (normalised && ch.name == "Z") continue;
        if (ch.type == ChannelType::UInt32)
            std::memcpy(out->hostUInt(ch.name), in->hostUInt(ch.name), n * sizeof(std::uint32_t));
        else
            std::memcpy(out->hostFloat(ch.name), in->hostFloat(ch.name), n * sizeof(float));
    }
    if (normalised) {
        float* dst = out->hostFloat("Z");
        const int w = in->width();
        const float inf = std::numeric_limits<float>::infinity();
        ctx.parallelFor(0, in->height(), 16, [&](int y0, int y1) {
            for (std::size_t i = std::size_t(y0) * w; i < std::size_t(y1) * w; ++i) {
                const float d = z[i];
                // 1.0 is TTK's "no hit" (and depth clamped at far): background.
                dst[i] = !std::isfinite(d) || d >= 1.f ? inf : float(nearValue + double(d) * (farValue - nearValue));
            }
        });
        std::ostringstream s;
        s << "normalised depth; Z = near + d (far - near) with near " << nearValue << " far " << farValue << " ("
          << who << "); 1.0 -> +inf";
        out->metadata().attributes["depth.convention"] = s.str();
    }
    if (!keepExisting) out->metadata().attributes["camera.source"] = who;
    if (ctx.cancelled()) return;
    ctx.progress(1.0);
    ctx.setOutput("image", BufferPtr(std::move(out)));
}

}  // namespace darkroom
