#include <darkroom/channel_text.h>
#include <darkroom/depth_input.h>
#include <darkroom/error.h>
#include <darkroom/product_database.h>

#include <cmath>
#include <cstdio>
#include <limits>

namespace darkroom {

namespace {

std::string number(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", v);
    return text;
}

}  // namespace

std::string ImageSpaceView::describe() const {
    const Camera& c = camera;
    std::string zText;
    if (normalised)
        zText = "Z read as depth normalised to [0, 1] between near and far (TTK's convention" +
                std::string(decidedByValues ? "; every finite Z lies in [0, 1]" : "") + ")";
    else
        zText = "Z read as raw distances; the view is as high as the image's depth range (Z from " + number(zMin) +
                " to " + number(zMax) + " here)";
    return "the image carries no camera, so it is shaded in image space: an orthographic camera looking along "
           "-z, the image " + number(c.viewHeight) + " unit(s) high (a pixel is " +
           number(c.viewHeight / (c.height > 0 ? c.height : 1)) + " unit(s)), " + zText +
           ". Radii as fractions of the image height mean what they always do; world radii are in these units. "
           "Set 'depthWithoutCamera' to read Z otherwise, or add a Camera node with the real camera";
}

Camera imageSpaceCamera(int width, int height, double viewHeight) {
    Camera c;
    c.position = {0, 0, 0};
    c.forward = {0, 0, -1};
    c.up = {0, 1, 0};
    c.projection = Camera::Projection::Orthographic;
    c.viewHeight = viewHeight;
    c.width = width;
    c.height = height;
    return c;
}

ImageSpaceView assumeImageSpace(const float* z, int width, int height, DepthWithoutCamera mode) {
    ImageSpaceView v;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    const std::size_t n = std::size_t(width > 0 ? width : 0) * std::size_t(height > 0 ? height : 0);
    for (std::size_t i = 0; i < n; ++i)
        if (std::isfinite(z[i])) {
            lo = std::min(lo, double(z[i]));
            hi = std::max(hi, double(z[i]));
        }
    if (lo <= hi) v.zMin = lo, v.zMax = hi;
    const bool within01 = v.zMin >= 0.0 && v.zMax <= 1.0;
    v.normalised = mode == DepthWithoutCamera::Normalised || (mode == DepthWithoutCamera::Automatic && within01);
    v.decidedByValues = mode == DepthWithoutCamera::Automatic && v.normalised;
    const double range = v.zMax - v.zMin;
    v.camera = imageSpaceCamera(width, height, v.normalised || !(range > 0) ? 1.0 : range);
    return v;
}

std::string missingDepthMessage(const Buffer& in) {
    if (const auto type = in.channelType("Z"))
        return std::string("expected depth 'Z' as float32 but it is ") + toString(*type);
    const auto& attributes = in.metadata().attributes;
    const auto source = attributes.find("source");
    const std::string channels = channelListText(in);
    const std::string need = "; depth-based passes need a depth channel (CISDepth in a composable image set, Z "
                             "in an EXR or a Darkroom database)";
    if (source != attributes.end()) {
        if (const std::string db = databaseOfProduct(source->second); !db.empty())
            return "database " + db + " stores no depth (channels: " + channels + ")" + need;
        return source->second + " stores no depth (channels: " + channels + ")" + need;
    }
    return "the image has no depth channel 'Z' (channels: " + channels + ")" + need;
}

const float* requireDepth(const Buffer& in) {
    if (const float* z = in.hostFloat("Z")) return z;
    throw Error(missingDepthMessage(in));
}

Camera cameraOrImageSpace(const Buffer& in, const float* z, DepthWithoutCamera mode, std::string* assumption) {
    if (in.metadata().camera) {
        Camera c = *in.metadata().camera;
        c.width = in.width();
        c.height = in.height();
        return c;
    }
    const ImageSpaceView v = assumeImageSpace(z, in.width(), in.height(), mode);
    if (assumption) *assumption = v.describe();
    return v.camera;
}

}  // namespace darkroom
