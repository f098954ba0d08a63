#include "exr_metadata.h"

#include "stored_attributes.h"

#include <darkroom/error.h>
#include <darkroom/port.h>
#include <darkroom/value.h>

#include <ImfDoubleAttribute.h>
#include <ImfFloatAttribute.h>
#include <ImfIntAttribute.h>
#include <ImfStringAttribute.h>
#include <ImfVecAttribute.h>

#include <sstream>

namespace darkroom::io::exr {

namespace {

const std::string kCamera = "darkroom:camera:";
const std::string kAttr = "darkroom:attr:";
const char* const kChannels = "darkroom:channels";

const Imf::Attribute& require(const Imf::Header& h, const std::string& name) {
    auto it = h.find(name);
    if (it == h.end()) throw Error("attribute '" + name + "' is missing although other camera attributes are present");
    return it.attribute();
}

// Double or float vectors, or the "[x, y, z]" text form, so files written by
// other tools (which often use V3f) are read too.
Vec3 getVec3(const Imf::Header& h, const std::string& name) {
    const Imf::Attribute& a = require(h, name);
    if (auto* d = dynamic_cast<const Imf::V3dAttribute*>(&a)) return {d->value().x, d->value().y, d->value().z};
    if (auto* f = dynamic_cast<const Imf::V3fAttribute*>(&a)) return {f->value().x, f->value().y, f->value().z};
    if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) return parseValue(PortType::Vec3, s->value()).asVec3();
    throw Error("attribute '" + name + "' must be a vector of three numbers, not " + a.typeName());
}

double getDouble(const Imf::Header& h, const std::string& name) {
    const Imf::Attribute& a = require(h, name);
    if (auto* d = dynamic_cast<const Imf::DoubleAttribute*>(&a)) return d->value();
    if (auto* f = dynamic_cast<const Imf::FloatAttribute*>(&a)) return f->value();
    if (auto* i = dynamic_cast<const Imf::IntAttribute*>(&a)) return i->value();
    if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) return parseValue(PortType::Float, s->value()).asFloat();
    throw Error("attribute '" + name + "' must be a number, not " + a.typeName());
}

int getInt(const Imf::Header& h, const std::string& name) {
    const Imf::Attribute& a = require(h, name);
    if (auto* i = dynamic_cast<const Imf::IntAttribute*>(&a)) return i->value();
    if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&a)) return int(parseValue(PortType::Int, s->value()).asInt());
    throw Error("attribute '" + name + "' must be an integer, not " + a.typeName());
}

std::string getString(const Imf::Header& h, const std::string& name, const std::string& otherwise) {
    auto* s = h.findTypedAttribute<Imf::StringAttribute>(name);
    return s ? s->value() : otherwise;
}

}  // namespace

void putMetadata(const BufferMetadata& meta, const std::vector<std::string>& channelOrder, Imf::Header& header) {
    if (meta.camera) {
        const Camera& c = *meta.camera;
        auto vec = [](const Vec3& v) { return Imf::V3dAttribute(Imath::V3d(v.x, v.y, v.z)); };
        header.insert(kCamera + "position", vec(c.position));
        header.insert(kCamera + "forward", vec(c.forward));
        header.insert(kCamera + "up", vec(c.up));
        header.insert(kCamera + "projection", Imf::StringAttribute(toString(c.projection)));
        header.insert(kCamera + "fovY", Imf::DoubleAttribute(c.fovYDegrees));
        header.insert(kCamera + "viewHeight", Imf::DoubleAttribute(c.viewHeight));
        header.insert(kCamera + "width", Imf::IntAttribute(c.width));
        header.insert(kCamera + "height", Imf::IntAttribute(c.height));
    }
    for (const auto& [key, value] : meta.attributes)
        if (isStoredAttribute(key)) header.insert(kAttr + key, Imf::StringAttribute(value));
    std::string order;
    for (const auto& n : channelOrder) order += (order.empty() ? "" : ",") + n;
    header.insert(kChannels, Imf::StringAttribute(order));
}

std::vector<std::string> getMetadata(const Imf::Header& header, BufferMetadata& meta) {
    bool anyCamera = false;
    for (auto it = header.begin(); it != header.end(); ++it) {
        const std::string name = it.name();
        if (name.rfind(kCamera, 0) == 0) anyCamera = true;
        if (name.rfind(kAttr, 0) == 0 && name.size() > kAttr.size()) {
            if (auto* s = dynamic_cast<const Imf::StringAttribute*>(&it.attribute()))
                meta.attributes[name.substr(kAttr.size())] = s->value();
        }
    }
    if (anyCamera) {
        Camera c;
        c.position = getVec3(header, kCamera + "position");
        c.forward = getVec3(header, kCamera + "forward");
        c.up = getVec3(header, kCamera + "up");
        const std::string proj = getString(header, kCamera + "projection", "perspective");
        if (proj == "perspective")
            c.projection = Camera::Projection::Perspective;
        else if (proj == "orthographic")
            c.projection = Camera::Projection::Orthographic;
        else
            throw Error("attribute '" + kCamera + "projection' must be perspective or orthographic, not '" + proj +
                        "'");
        c.fovYDegrees = getDouble(header, kCamera + "fovY");
        c.viewHeight = getDouble(header, kCamera + "viewHeight");
        c.width = getInt(header, kCamera + "width");
        c.height = getInt(header, kCamera + "height");
        meta.camera = c;
    }
    std::vector<std::string> order;
    std::stringstream ss(getString(header, kChannels, ""));
    for (std::string n; std::getline(ss, n, ',');) order.push_back(n);
    return order;
}

}  // namespace darkroom::io::exr
