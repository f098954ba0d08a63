#include "gbuffer_writer.h"

#include <darkroom/error.h>

#include <set>

namespace darkroom::embree {

std::vector<ChannelDesc> GBufferWriter::channels(const CaptureRequest& request) {
    std::vector<ChannelDesc> out{{"Z", ChannelType::Float32}};
    static const std::set<std::string> reserved{"Z", "N.x", "N.y", "N.z", "objectId", "primitiveId"};
    std::set<std::string> seen;
    for (const auto& s : request.scalars) {
        if (s.empty()) throw Error("capture: a requested scalar field has an empty name");
        if (reserved.count(s))
            throw Error("capture: scalar field '" + s +
                        "' clashes with a G-buffer channel of the same name (Z, N.x, N.y, N.z, objectId, "
                        "primitiveId); rename the field");
        if (!seen.insert(s).second) throw Error("capture: scalar field '" + s + "' is requested twice");
        out.push_back({s, ChannelType::Float32});
    }
    if (request.normals) {
        out.push_back({"N.x", ChannelType::Float32});
        out.push_back({"N.y", ChannelType::Float32});
        out.push_back({"N.z", ChannelType::Float32});
    }
    if (request.objectId) out.push_back({"objectId", ChannelType::UInt32});
    if (request.primitiveId) out.push_back({"primitiveId", ChannelType::UInt32});
    return out;
}

GBufferWriter::GBufferWriter(const std::vector<ObjectView>& objects, const CaptureRequest& request,
                             WritableBuffer& buffer) {
    for (const auto& o : objects)
        objects_.push_back({o.representation, o.vertices, o.vertexStride, o.indices, o.primitiveCell});
    z_ = buffer.writeFloat("Z");
    for (const auto& name : request.scalars) {
        scalars_.push_back(buffer.writeFloat(name));
        for (const auto& o : objects) {
            FieldRef ref;
            if (const FieldView* f = o.field(name)) {
                ref.values = f->values;
                ref.cell = f->cell;
            }
            fields_.push_back(ref);
        }
    }
    if (request.normals) {
        n_[0] = buffer.writeFloat("N.x");
        n_[1] = buffer.writeFloat("N.y");
        n_[2] = buffer.writeFloat("N.z");
    }
    if (request.objectId) objectId_ = buffer.writeUInt("objectId");
    if (request.primitiveId) primitiveId_ = buffer.writeUInt("primitiveId");
}

}  // namespace darkroom::embree
