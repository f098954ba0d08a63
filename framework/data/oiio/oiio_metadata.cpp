#include "oiio_metadata.h"

#include <darkroom/error.h>
#include <darkroom/port.h>
#include <darkroom/value.h>

#include <sstream>

namespace darkroom::io {

namespace {

const std::string kCamera = "darkroom:camera:";
const std::string kAttr = "darkroom:attr:";
const char* const kChannels = "darkroom:channels";
const OIIO::TypeDesc kDoubleVec3(OIIO::TypeDesc::DOUBLE, OIIO::TypeDesc::VEC3);

void putVec3(OIIO::ImageSpec& spec, const std::string& name, const Vec3& v) {
    const double d[3] = {v.x, v.y, v.z};
    spec.attribute(name, kDoubleVec3, d);
}

void putDouble(OIIO::ImageSpec& spec, const std::string& name, double v) {
    spec.attribute(name, OIIO::TypeDesc::DOUBLE, &v);
}

const OIIO::ParamValue& require(const OIIO::ImageSpec& spec, const std::string& name) {
    const OIIO::ParamValue* p = spec.find_attribute(name);
    if (!p) throw Error("attribute '" + name + "' is missing although other camera attributes are present");
    return *p;
}

// Double or float vectors, or the "[x, y, z]" text form, so files written by
// other tools (which often use V3f) are read too.
Vec3 getVec3(const OIIO::ImageSpec& spec, const std::string& name) {
    const OIIO::ParamValue& p = require(spec, name);
    const OIIO::TypeDesc t = p.type();
    if (t.basetype == OIIO::TypeDesc::STRING) return parseValue(PortType::Vec3, p.get_string()).asVec3();
    if (t.basevalues() == 3 && t.basetype == OIIO::TypeDesc::DOUBLE) {
        const double* d = static_cast<const double*>(p.data());
        return {d[0], d[1], d[2]};
    }
    if (t.basevalues() == 3 && t.basetype == OIIO::TypeDesc::FLOAT) {
        const float* d = static_cast<const float*>(p.data());
        return {d[0], d[1], d[2]};
    }
    throw Error("attribute '" + name + "' must be a vector of three numbers, not " + std::string(t.c_str()));
}

double getDouble(const OIIO::ImageSpec& spec, const std::string& name) {
    const OIIO::ParamValue& p = require(spec, name);
    const OIIO::TypeDesc t = p.type();
    if (t == OIIO::TypeDesc::DOUBLE) return *static_cast<const double*>(p.data());
    if (t == OIIO::TypeDesc::FLOAT) return *static_cast<const float*>(p.data());
    if (t == OIIO::TypeDesc::INT) return *static_cast<const int*>(p.data());
    if (t == OIIO::TypeDesc::STRING) return parseValue(PortType::Float, p.get_string()).asFloat();
    throw Error("attribute '" + name + "' must be a number, not " + std::string(t.c_str()));
}

int getInt(const OIIO::ImageSpec& spec, const std::string& name) {
    const OIIO::ParamValue& p = require(spec, name);
    if (p.type() == OIIO::TypeDesc::INT) return *static_cast<const int*>(p.data());
    if (p.type() == OIIO::TypeDesc::STRING) return int(parseValue(PortType::Int, p.get_string()).asInt());
    throw Error("attribute '" + name + "' must be an integer, not " + std::string(p.type().c_str()));
}

}  // namespace

void putMetadata(const BufferMetadata& meta, const std::vector<std::string>& channelOrder,
                 OIIO::ImageSpec& spec) {
    if (meta.camera) {
        const Camera& c = *meta.camera;
        putVec3(spec, kCamera + "position", c.position);
        putVec3(spec, kCamera + "forward", c.forward);
        putVec3(spec, kCamera + "up", c.up);
        spec.attribute(kCamera + "projection", toString(c.projection));
        putDouble(spec, kCamera + "fovY", c.fovYDegrees);
        putDouble(spec, kCamera + "viewHeight", c.viewHeight);
        spec.attribute(kCamera + "width", c.width);
        spec.attribute(kCamera + "height", c.height);
    }
    for (const auto& [key, value] : meta.attributes) spec.attribute(kAttr + key, value);
    std::string order;
    for (const auto& n : channelOrder) order += (order.empty() ? "" : ",") + n;
    spec.attribute(kChannels, order);
}

std::vector<std::string> getMetadata(const OIIO::ImageSpec& spec, BufferMetadata& meta) {
    bool anyCamera = false;
    for (const auto& p : spec.extra_attribs) {
        const std::string name = p.name().string();
        if (name.rfind(kCamera, 0) == 0) anyCamera = true;
        if (name.rfind(kAttr, 0) == 0 && name.size() > kAttr.size())
            meta.attributes[name.substr(kAttr.size())] = p.get_string();
    }
    if (anyCamera) {
        Camera c;
        c.position = getVec3(spec, kCamera + "position");
        c.forward = getVec3(spec, kCamera + "forward");
        c.up = getVec3(spec, kCamera + "up");
        const std::string proj = spec.get_string_attribute(kCamera + "projection", "perspective");
        if (proj == "perspective")
            c.projection = Camera::Projection::Perspective;
        else if (proj == "orthographic")
            c.projection = Camera::Projection::Orthographic;
        else
            throw Error("attribute '" + kCamera + "projection' must be perspective or orthographic, not '" +
                        proj + "'");
        c.fovYDegrees = getDouble(spec, kCamera + "fovY");
        c.viewHeight = getDouble(spec, kCamera + "viewHeight");
        c.width = getInt(spec, kCamera + "width");
        c.height = getInt(spec, kCamera + "height");
        meta.camera = c;
    }
    std::vector<std::string> order;
    const std::string text = spec.get_string_attribute(kChannels);
    std::stringstream ss(text);
    for (std::string n; std::getline(ss, n, ',');) order.push_back(n);
    return order;
}

}  // namespace darkroom::io
