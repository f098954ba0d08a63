#include "camera_node.h"

#include "camera_from_view.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace darkroom {

void CameraNode::execute(Context& ctx) {
    const std::string who = "Camera '" + ctx.nodeName() + "'";  // provenance in the metadata
    const BufferPtr in = ctx.get(image_);
    const bool keepExisting = ctx.get(apply_) == Apply::WhenMissing && in->metadata().camera.has_value();
    const bool normalised = ctx.get(depth_) == Depth::Normalised;
    if (keepExisting && !normalised) {
        ctx.set(result_, in);  // nothing to change
        return;
    }
    ParaViewCamera view;
    view.position = ctx.get(position_);
    view.focalPoint = ctx.get(focalPoint_);
    view.viewUp = ctx.get(viewUp_);
    view.parallelProjection = ctx.get(parallelProjection_);
    view.viewAngle = ctx.get(viewAngle_);
    view.parallelScale = ctx.get(parallelScale_);
    const Camera camera = cameraFromParaView(view, in->width(), in->height());

    const double nearValue = ctx.get(near_), farValue = ctx.get(far_);
    const float* z = nullptr;
    if (normalised) {
        if (!(farValue > nearValue))
            throw Error("far (" + std::to_string(farValue) + ") must be greater than near (" +
                        std::to_string(nearValue) + ") to convert normalised depth");
        z = in->hostFloat("Z");
        if (!z) {
            std::string names;
            for (const auto& n : in->channelNames()) names += (names.empty() ? "" : ", ") + n;
            throw Error("depth 'normalised' needs a float channel Z; the image has " +
                        (names.empty() ? std::string("no channels") : names));
        }
        // Converting twice (or distances) would be silently wrong: refuse values outside [0, 1].
        for (std::size_t i = 0; i < in->pixelCount(); ++i)
            if (std::isfinite(z[i]) && (z[i] < 0.f || z[i] > 1.f)) {
                std::ostringstream s;
                s << "depth 'normalised' expects Z in [0, 1] (or +inf for background), but pixel ("
                  << i % std::size_t(in->width()) << ", " << i / std::size_t(in->width()) << ") holds " << z[i]
                  << "; is Z already a distance? Use depth 'distance'";
                throw Error(s.str());
            }
    }

    // Every channel is shared with the input; only a converted Z is new (all
    // of its pixels written below).
    auto out = ctx.derive(in, normalised ? std::vector<ChannelDesc>{"Z"} : std::vector<ChannelDesc>{}, Fill::None);
    if (!keepExisting) out->metadata().camera = camera;
    if (normalised) {
        float* dst = out->writeFloat("Z");
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
    ctx.progress(1.0);
    ctx.set(result_, out);
}

}  // namespace darkroom
