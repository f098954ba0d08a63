#include "embree_backend.h"

#include "embree_scene.h"
#include "flush_denormals.h"
#include "gbuffer_writer.h"
#include "layered_tile.h"
#include "nearest_hit_rule.h"
#include "packet_rows.h"
#include "primary_packet.h"
#include "primary_rays.h"

#include <darkroom/error.h>
#include <embree3/rtcore.h>

#include <cmath>
#include <limits>

namespace darkroom::embree {

namespace {

// Tiles are the unit of parallel work; packets are 4x2 pixel blocks inside a
// tile, since square-ish blocks keep the 8 rays of a packet close together and
// traverse the BVH with the same nodes (Embree's packet traversal benefits
// from coherence; the COHERENT flag says so). The split is fixed, whatever the
// thread count, so every pixel is traced in the same packet every time.
constexpr int kTile = 16;
static_assert(kTile % kPacketW == 0 && kTile % kPacketH == 0);

class EmbreeBackend final : public CaptureBackend {
public:
    EmbreeBackend() : device_(std::make_shared<Device>()) {}

    void setScene(std::shared_ptr<const Scene> scene) override {
        bvh_.reset();  // release the old BVH before building the next one
        bvh_ = std::make_unique<SceneBvh>(device_, std::move(scene));
    }

    BufferPtr render(const Camera& camera, const CaptureRequest& request, Context& ctx) override {
        if (!bvh_) throw Error("embree capture: render() called before setScene()");
        return renderGBuffer(*bvh_, camera, request, ctx);
    }

    static BufferPtr renderTiles(const SceneBvh& bvh, const Camera& camera, const CaptureRequest& request,
                                 Context& ctx, LayerMethod method) {
        if (camera.width <= 0 || camera.height <= 0)
            throw Error("embree capture: the camera's resolution is " + std::to_string(camera.width) + "x" +
                        std::to_string(camera.height) + "; expected a positive width and height");
        if (!(camera.halfHeight() > 0) || !std::isfinite(camera.halfHeight()))
            throw Error("embree capture: the camera's field of view / view height must be positive and finite");

        // Every pixel is written (hit or miss): no zero fill.
        auto buffer = ctx.allocate(camera.width, camera.height, GBufferWriter::channels(request), Fill::None);
        buffer->metadata().camera = camera;
        buffer->metadata().attributes["units.Z"] = "world";
        const PrimaryRays rays(camera);
        const int tilesX = (camera.width + kTile - 1) / kTile;
        const int tilesY = (camera.height + kTile - 1) / kTile;
        RTCScene scene = bvh.handle();
        if (request.layers > 1) {
            renderLayers(bvh, camera, request, rays, method, *buffer, ctx);
            return buffer;
        }
        const GBufferWriter writer(bvh.objects(), bvh.pieces(), request, *buffer);
        ctx.parallelFor(0, tilesX * tilesY, 1, [&](int begin, int end) {
            const FlushDenormals ftz;
            NearestHitContext ic(RTC_INTERSECT_CONTEXT_FLAG_COHERENT);
            TileBuffer buffer = writer.tileBuffer();
            for (int tile = begin; tile < end; ++tile) {
                if (ctx.cancelled()) break;
                traceTile(scene, &ic, rays, writer, buffer, camera.width, camera.height, (tile % tilesX) * kTile,
                          (tile / tilesX) * kTile);
            }
            finishRows();  // the streaming stores of this thread, before others read the planes
        });
        if (ctx.cancelled()) throw Cancelled();
        ctx.progress(1.0);
        return buffer;
    }

    // Layered G-buffers (request.layers > 1): the tiles as renderTiles splits
    // them, each pixel's K nearest crossings written by one writer per layer.
    static void renderLayers(const SceneBvh& bvh, const Camera& camera, const CaptureRequest& request,
                             const PrimaryRays& rays, LayerMethod method, WritableBuffer& buffer, Context& ctx) {
        std::vector<GBufferWriter> writers;
        for (int k = 0; k < request.layers; ++k) writers.emplace_back(bvh.objects(), bvh.pieces(), request, buffer, k);
        const int tilesX = (camera.width + kTile - 1) / kTile;
        const int tilesY = (camera.height + kTile - 1) / kTile;
        ctx.parallelFor(0, tilesX * tilesY, 1, [&](int begin, int end) {
            const FlushDenormals ftz;
            LayeredTileState state(writers);
            for (int tile = begin; tile < end; ++tile) {
                if (ctx.cancelled()) break;
                traceLayeredTile(bvh, method, rays, writers, state, camera.width, camera.height,
                                 (tile % tilesX) * kTile, (tile / tilesX) * kTile);
            }
            finishRows();
        });
        if (ctx.cancelled()) throw Cancelled();
        ctx.progress(1.0);
    }

    BufferPtr trace(const RayBatch& rays, const CaptureRequest& request, Context& ctx) override {
        if (!bvh_) throw Error("embree capture: trace() called before setScene()");
        if (request.layers != 1)
            throw Error("embree capture: trace() answers the nearest hit of each ray; layers = " +
                        std::to_string(request.layers) + " is for render()");
        const std::size_t n = checkBatch(rays, "trace");
        auto buffer = ctx.allocate(int(n), 1, GBufferWriter::channels(request));
        buffer->metadata().attributes["units.Z"] = "ray parameter";
        const GBufferWriter writer(bvh_->objects(), bvh_->pieces(), request, *buffer);
        RTCScene scene = bvh_->handle();
        const int packets = int((n + 7) / 8);
        ctx.parallelFor(0, packets, kBatchPacketsPerTask, [&](int begin, int end) {
            const FlushDenormals ftz;
            NearestHitContext ic(RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT);
            alignas(32) RTCRayHit8 rh;
            alignas(32) int valid[8];
            for (int p = begin; p < end; ++p) {
                if (ctx.cancelled()) return;
                const std::size_t first = std::size_t(p) * 8;
                loadPacket(rays, first, n, rh.ray, valid);
                for (int k = 0; k < 8; ++k) {
                    rh.hit.geomID[k] = RTC_INVALID_GEOMETRY_ID;
                    rh.hit.instID[0][k] = RTC_INVALID_GEOMETRY_ID;
                }
                ic.reset();
                rtcIntersect8(valid, scene, &ic.context, &rh);
                for (int k = 0; k < 8; ++k) {
                    if (!valid[k]) continue;
                    const std::size_t i = first + std::size_t(k);
                    if (rh.hit.geomID[k] == RTC_INVALID_GEOMETRY_ID) {
                        writer.miss(i);
                        continue;
                    }
                    const SurfaceHit h{rh.ray.tfar[k], rh.hit.geomID[k], rh.hit.primID[k], rh.hit.u[k], rh.hit.v[k],
                                       {rh.hit.Ng_x[k], rh.hit.Ng_y[k], rh.hit.Ng_z[k]}};
                    writer.hit(i, h, &rays.origins[3 * i], &rays.directions[3 * i]);
                }
            }
        });
        if (ctx.cancelled()) throw Cancelled();
        return buffer;
    }

    void occluded(const RayBatch& rays, std::vector<std::uint8_t>& hit, Context& ctx) override {
        if (!bvh_) throw Error("embree capture: occluded() called before setScene()");
        const std::size_t n = checkBatch(rays, "occluded");
        hit.assign(n, 0);
        RTCScene scene = bvh_->handle();
        const int packets = int((n + 7) / 8);
        ctx.parallelFor(0, packets, kBatchPacketsPerTask, [&](int begin, int end) {
            const FlushDenormals ftz;
            RTCIntersectContext ic;
            rtcInitIntersectContext(&ic);
            ic.flags = RTC_INTERSECT_CONTEXT_FLAG_INCOHERENT;
            alignas(32) RTCRay8 ray;
            alignas(32) int valid[8];
            for (int p = begin; p < end; ++p) {
                if (ctx.cancelled()) return;
                const std::size_t first = std::size_t(p) * 8;
                loadPacket(rays, first, n, ray, valid);
                rtcOccluded8(valid, scene, &ic, &ray);
                // Embree marks an occluded ray by setting tfar to -inf.
                for (int k = 0; k < 8; ++k)
                    if (valid[k] && ray.tfar[k] < 0.0f) hit[first + std::size_t(k)] = 1;
            }
        });
        if (ctx.cancelled()) throw Cancelled();
    }

private:
    // 64 packets (512 rays) per task: enough work to amortise scheduling,
    // small enough to balance across threads for batches of a few thousand.
    static constexpr int kBatchPacketsPerTask = 64;

    static std::size_t checkBatch(const RayBatch& rays, const char* what) {
        const std::size_t n = rays.size();
        if (rays.origins.size() != 3 * n || rays.directions.size() != rays.origins.size())
            throw Error(std::string("embree capture: ") + what + "(): the ray batch has " +
                        std::to_string(rays.origins.size()) + " origin and " +
                        std::to_string(rays.directions.size()) +
                        " direction components; expected 3 of each per ray");
        if (!rays.tFar.empty() && rays.tFar.size() != n)
            throw Error(std::string("embree capture: ") + what + "(): the ray batch has " +
                        std::to_string(rays.tFar.size()) + " tFar values for " + std::to_string(n) +
                        " rays; expected one per ray or none");
        if (n == 0 || n > std::size_t(std::numeric_limits<int>::max()))
            throw Error(std::string("embree capture: ") + what + "(): a ray batch needs 1 to " +
                        std::to_string(std::numeric_limits<int>::max()) + " rays, got " + std::to_string(n));
        return n;
    }

    // Fills the 8 lanes from rays [first, first + 8); lanes past the end are
    // switched off.
    static void loadPacket(const RayBatch& rays, std::size_t first, std::size_t n, RTCRay8& r, int valid[8]) {
        for (int k = 0; k < 8; ++k) {
            const std::size_t i = first + std::size_t(k);
            valid[k] = i < n ? -1 : 0;
            const std::size_t j = i < n ? i : first;
            r.org_x[k] = rays.origins[3 * j];
            r.org_y[k] = rays.origins[3 * j + 1];
            r.org_z[k] = rays.origins[3 * j + 2];
            r.dir_x[k] = rays.directions[3 * j];
            r.dir_y[k] = rays.directions[3 * j + 1];
            r.dir_z[k] = rays.directions[3 * j + 2];
            r.tnear[k] = rays.tNear;
            r.tfar[k] = rays.tFar.empty() ? std::numeric_limits<float>::infinity() : rays.tFar[j];
            r.time[k] = 0.0f;
            r.mask[k] = 0xFFFFFFFFu;
            r.id[k] = unsigned(k);
            r.flags[k] = 0;
        }
    }

    // The packets of one tile into `buffer`, then the tile into the planes. A
    // packet's G-buffer is written two packets after its trace: the indices of
    // the primitives it hit are prefetched right after its trace, the field
    // values at those indices one packet later, so both have arrived when the
    // packet is written.
    static void traceTile(RTCScene scene, NearestHitContext* ic, const PrimaryRays& rays, const GBufferWriter& writer,
                          TileBuffer& buffer, int width, int height, int x0, int y0) {
        static_assert(kTile == TileBuffer::kSize);
        static_assert(RTC_INVALID_GEOMETRY_ID == GBufferWriter::kMissID);
        using Packet = PrimaryPacket;
        constexpr int kInFlight = 3;
        Packet packets[kInFlight];
        for (Packet& p : packets) setFixedRayFields(p);  // once for the tile
        auto hitsOf = [](Packet& p) {
            RTCRayHit8& rh = p.rh;
            return PacketHits{8, p.valid, rh.ray.tfar, rh.hit.geomID, rh.hit.primID, rh.hit.u, rh.hit.v,
                              {rh.hit.Ng_x, rh.hit.Ng_y, rh.hit.Ng_z}, {rh.ray.org_x, rh.ray.org_y, rh.ray.org_z},
                              {rh.ray.dir_x, rh.ray.dir_y, rh.ray.dir_z}};
        };
        const int x1 = std::min(x0 + kTile, width), y1 = std::min(y0 + kTile, height);
        int traced = 0;
        for (int py = y0; py < y1; py += kPacketH) {
            for (int px = x0; px < x1; px += kPacketW) {
                Packet& p = packets[traced % kInFlight];
                RTCRayHit8& rh = p.rh;
                loadPrimaryRays(p, rays, px, py, x0, y0, x1, y1);
                ic->reset();
                rtcIntersect8(p.valid, scene, &ic->context, &rh);
                for (int k = 0; k < 8; ++k)
                    if (p.valid[k] && rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID)
                        writer.prefetch(SurfaceHit{0.0f, rh.hit.geomID[k], rh.hit.primID[k], 0.0f, 0.0f, {}});
                if (traced >= 1) {
                    Packet& previous = packets[(traced - 1) % kInFlight];
                    for (int k = 0; k < 8; ++k)
                        if (previous.valid[k] && previous.rh.hit.geomID[k] != RTC_INVALID_GEOMETRY_ID)
                            writer.prefetchFields(
                                SurfaceHit{0.0f, previous.rh.hit.geomID[k], previous.rh.hit.primID[k], 0.0f, 0.0f, {}});
                }
                if (traced >= 2) {
                    Packet& ready = packets[(traced - 2) % kInFlight];
                    writer.packet(hitsOf(ready), ready.cell, buffer);
                }
                ++traced;
            }
        }
        for (int i = std::max(0, traced - 2); i < traced; ++i) writer.packet(hitsOf(packets[i % kInFlight]), packets[i % kInFlight].cell, buffer);
        writer.flush(buffer, x0, y0, x1 - x0, y1 - y0, width);
    }

    std::shared_ptr<Device> device_;
    std::unique_ptr<SceneBvh> bvh_;
};

}  // namespace

std::unique_ptr<CaptureBackend> createBackend() { return std::make_unique<EmbreeBackend>(); }

BufferPtr renderGBuffer(const SceneBvh& bvh, const Camera& camera, const CaptureRequest& request, Context& ctx,
                        LayerMethod method) {
    return EmbreeBackend::renderTiles(bvh, camera, request, ctx, method);
}

}  // namespace darkroom::embree
