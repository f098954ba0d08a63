#include "gbuffer_writer.h"

#include "packet_rows.h"

#include <darkroom/error.h>
#include <darkroom/layers.h>

#include <algorithm>
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
        if (request.layers > 1 && layers::parse(s).first != 0)
            throw Error("capture: scalar field '" + s + "' has the name of a channel of layer " +
                        std::to_string(layers::parse(s).first) + " (darkroom/layers.h); rename the field");
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
    if (request.layers < 1 || request.layers > CaptureRequest::kMaxLayers)
        throw Error("capture: " + std::to_string(request.layers) + " layers requested; expected 1 to " +
                    std::to_string(CaptureRequest::kMaxLayers) + " surface crossings per pixel");
    // Layer k >= 1 repeats layer 0's channels under darkroom/layers.h's names.
    const std::size_t front = out.size();
    for (int k = 1; k < request.layers; ++k)
        for (std::size_t c = 0; c < front; ++c) out.push_back({layers::channel(out[c].name, k), out[c].type});
    return out;
}

GBufferWriter::GBufferWriter(const std::vector<ObjectView>& objects, const std::vector<GeometryPiece>& pieces,
                             const CaptureRequest& request, WritableBuffer& buffer, int layer) {
    auto name = [layer](const std::string& n) { return layers::channel(n, layer); };
    std::vector<GeometryPiece> whole;
    for (std::size_t i = 0; pieces.empty() && i < objects.size(); ++i) whole.push_back({std::uint32_t(i), 0});
    const std::vector<GeometryPiece>& geometries = pieces.empty() ? whole : pieces;
    for (const GeometryPiece& g : geometries) {
        const ObjectView& o = objects[g.object];
        const std::size_t first = g.firstPrimitive;
        const std::size_t indicesPer = o.representation == Representation::Surface ? 3 : 1;
        objects_.push_back({o.representation, o.vertices, o.vertexStride, o.indices ? o.indices + indicesPer * first : nullptr,
                            o.primitiveCell ? o.primitiveCell + first : nullptr,
                            {o.normals[0], o.normals[1], o.normals[2]}, g.object, std::uint32_t(first)});
        pieces_ = pieces_ || first > 0 || g.object != objects_.size() - 1;
        hasPoints_ = hasPoints_ || o.representation == Representation::Points;
        hasSmooth_ = hasSmooth_ || (request.normals && o.normals[0]);
    }
    z_ = buffer.writeFloat(name("Z"));
    for (const auto& scalar : request.scalars) {
        scalars_.push_back(buffer.writeFloat(name(scalar)));
        for (const GeometryPiece& g : geometries) {
            FieldRef ref;
            if (const FieldView* f = objects[g.object].field(scalar)) {
                // A cell field without a cell map is indexed by primitive.
                const bool byPrimitive = f->cell && !objects[g.object].primitiveCell;
                ref.values = f->values + (byPrimitive ? g.firstPrimitive : 0);
                ref.cell = f->cell;
            }
            fields_.push_back(ref);
        }
    }
    if (request.normals) {
        n_[0] = buffer.writeFloat(name("N.x"));
        n_[1] = buffer.writeFloat(name("N.y"));
        n_[2] = buffer.writeFloat(name("N.z"));
    }
    if (request.objectId) objectId_ = buffer.writeUInt(name("objectId"));
    if (request.primitiveId) primitiveId_ = buffer.writeUInt(name("primitiveId"));
}

void GBufferWriter::pieceIds(const PacketHits& p, const int* cell, TileBuffer& tile) const {
    for (int k = 0; k < p.lanes; ++k) {
        if (!p.valid[k] || p.geomID[k] == kMissID) continue;
        const ObjectRef& o = objects_[p.geomID[k]];
        const std::size_t c = std::size_t(cell[k]);
        if (objectId_) tile.objectId()[c] = o.object;
        if (primitiveId_) tile.primitiveId()[c] = o.firstPrimitive + p.primID[k];
    }
}

void GBufferWriter::packet(const PacketHits& p, const int* cell, TileBuffer& tile) const {
    // Depth, normals, ids and the scalars' NaN for all lanes a vector at a
    // time; then what differs per hit: sphere depth, the fields.
    const std::size_t nScalars = scalars_.size();
    float* scalarPlanes[64];
    float** scalars = nScalars <= 64 ? scalarPlanes : nullptr;
    std::vector<float*> many;
    if (!scalars) {
        many.resize(nScalars);
        scalars = many.data();
    }
    for (std::size_t s = 0; s < nScalars; ++s) scalars[s] = tile.channel(1 + s) + cell[0];
    PacketRowTargets t{tile.channel(0) + cell[0], {nullptr, nullptr, nullptr}, scalars, int(nScalars),
                       objectId_ ? tile.objectId() + cell[0] : nullptr, primitiveId_ ? tile.primitiveId() + cell[0] : nullptr,
                       TileBuffer::kSize};
    if (n_[0])
        for (std::size_t a = 0; a < 3; ++a) t.normal[a] = tile.channel(1 + nScalars + a) + cell[0];
    writePacketRows(p, t);
    if (pieces_ && (objectId_ || primitiveId_)) pieceIds(p, cell, tile);
    if (nScalars == 0 && !hasPoints_ && !hasSmooth_) return;
    const std::size_t nObjects = objects_.size();
    for (int k = 0; k < p.lanes; ++k) {
        if (!p.valid[k] || p.geomID[k] == kMissID) continue;
        const std::size_t c = std::size_t(cell[k]);
        const SurfaceHit h{p.t[k], p.geomID[k], p.primID[k], p.u[k], p.v[k], {p.ng[0][k], p.ng[1][k], p.ng[2][k]}};
        const ObjectRef& o = objects_[h.geomID];
        if (o.representation == Representation::Points) {
            const float org[3] = {p.org[0][k], p.org[1][k], p.org[2][k]};
            const float dir[3] = {p.dir[0][k], p.dir[1][k], p.dir[2][k]};
            tile.channel(0)[c] = refineDepth(o, h, org, dir);
        }
        for (std::size_t s = 0; s < nScalars; ++s) tile.channel(1 + s)[c] = sample(o, fields_[s * nObjects + h.geomID], h);
        if (smooth(o)) {
            // The facing geometric normal writePacketRows left is the fallback.
            float* plane[3] = {tile.channel(1 + nScalars), tile.channel(2 + nScalars), tile.channel(3 + nScalars)};
            float n[3] = {plane[0][c], plane[1][c], plane[2][c]};
            const float dir[3] = {p.dir[0][k], p.dir[1][k], p.dir[2][k]};
            smoothNormal(o, h, dir, n);
            plane[0][c] = n[0], plane[1][c] = n[1], plane[2][c] = n[2];
        }
    }
}

void GBufferWriter::flush(const TileBuffer& tile, int x0, int y0, int w, int h, int imageWidth) const {
    const std::size_t nScalars = scalars_.size();
    const std::size_t at = std::size_t(y0) * std::size_t(imageWidth) + std::size_t(x0);
    auto copy = [&](const void* from, void* plane) {
        copyRows(from, TileBuffer::kSize, static_cast<char*>(plane) + 4 * at, std::size_t(imageWidth), w, h);
    };
    copy(tile.channel(0), z_);
    for (std::size_t s = 0; s < nScalars; ++s) copy(tile.channel(1 + s), scalars_[s]);
    if (n_[0])
        for (std::size_t a = 0; a < 3; ++a) copy(tile.channel(1 + nScalars + a), n_[a]);
    if (objectId_) copy(tile.objectId(), objectId_);
    if (primitiveId_) copy(tile.primitiveId(), primitiveId_);
}

}  // namespace darkroom::embree
