#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "src/packet_rows.cpp"
#include <hwy/foreach_target.h>  // IWYU pragma: keep
#include <hwy/cache_control.h>
#include <hwy/highway.h>

#include "packet_rows.h"

#include <cstdint>
#include <limits>

HWY_BEFORE_NAMESPACE();
namespace darkroom::embree {
namespace HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

void WritePacketRows(const PacketHits& p, const PacketRowTargets& t) {
    const hn::CappedTag<float, 4> d;
    const hn::RebindToUnsigned<decltype(d)> du;
    constexpr int kRowLanes = 4;
    const auto zero = hn::Zero(d), one = hn::Set(d, 1.0f);
    const auto nan = hn::Set(d, std::numeric_limits<float>::quiet_NaN());
    const auto inf = hn::Set(d, std::numeric_limits<float>::infinity());
    const auto noId = hn::Set(du, GBufferWriter::kNoId);
    for (int row = 0; row < 2; ++row) {
        for (int part = 0; part < kRowLanes; part += int(hn::Lanes(d))) {
            const int k = row * kRowLanes + part;  // the first lane
            const std::size_t cell = std::size_t(row) * std::size_t(t.rowStride) + std::size_t(part);
            const auto geom = hn::LoadU(du, p.geomID + k);
            const auto hitU = hn::Ne(geom, hn::Set(du, GBufferWriter::kMissID));
            const auto hit = hn::RebindMask(d, hitU);
            hn::StoreU(hn::IfThenElse(hit, hn::LoadU(d, p.t + k), inf), d, t.z + cell);
            if (t.normal[0]) {
                const auto nx = hn::LoadU(d, p.ng[0] + k), ny = hn::LoadU(d, p.ng[1] + k), nz = hn::LoadU(d, p.ng[2] + k);
                const auto len = hn::Sqrt(hn::Add(hn::Add(hn::Mul(nx, nx), hn::Mul(ny, ny)), hn::Mul(nz, nz)));
                const auto along = hn::Add(hn::Add(hn::Mul(nx, hn::LoadU(d, p.dir[0] + k)), hn::Mul(ny, hn::LoadU(d, p.dir[1] + k))),
                                           hn::Mul(nz, hn::LoadU(d, p.dir[2] + k)));
                const auto sign = hn::IfThenElse(hn::Gt(along, zero), hn::Neg(one), one);
                const auto scale = hn::IfThenElse(hn::Gt(len, zero), hn::Div(sign, len), nan);
                hn::StoreU(hn::IfThenElse(hit, hn::Mul(nx, scale), nan), d, t.normal[0] + cell);
                hn::StoreU(hn::IfThenElse(hit, hn::Mul(ny, scale), nan), d, t.normal[1] + cell);
                hn::StoreU(hn::IfThenElse(hit, hn::Mul(nz, scale), nan), d, t.normal[2] + cell);
            }
            for (int s = 0; s < t.scalarCount; ++s) hn::StoreU(nan, d, t.scalars[s] + cell);
            if (t.objectId) hn::StoreU(hn::IfThenElse(hitU, geom, noId), du, t.objectId + cell);
            if (t.primitiveId) hn::StoreU(hn::IfThenElse(hitU, hn::LoadU(du, p.primID + k), noId), du, t.primitiveId + cell);
        }
    }
}

void CopyRows(const void* src, int srcStride, void* dst, std::size_t dstStride, int w, int h) {
    const hn::ScalableTag<float> d;
    const int lanes = int(hn::Lanes(d));
    const auto* from = static_cast<const float*>(src);
    auto* to = static_cast<float*>(dst);
    for (int y = 0; y < h; ++y) {
        const float* s = from + std::size_t(y) * std::size_t(srcStride);
        float* t = to + std::size_t(y) * dstStride;
        const bool stream = w % lanes == 0 && w * 4 % 64 == 0 && reinterpret_cast<std::uintptr_t>(t) % 64 == 0;
        if (stream) {
            for (int x = 0; x < w; x += lanes) hn::Stream(hn::LoadU(d, s + x), d, t + x);
        } else {
            for (int x = 0; x < w; ++x) t[x] = s[x];
        }
    }
}

void FinishRows() { hwy::FlushStream(); }

}  // namespace HWY_NAMESPACE
}  // namespace darkroom::embree
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace darkroom::embree {
HWY_EXPORT(WritePacketRows);
void writePacketRows(const PacketHits& p, const PacketRowTargets& t) { HWY_DYNAMIC_DISPATCH(WritePacketRows)(p, t); }
HWY_EXPORT(CopyRows);
HWY_EXPORT(FinishRows);
void copyRows(const void* src, int srcStride, void* dst, std::size_t dstStride, int w, int h) {
    HWY_DYNAMIC_DISPATCH(CopyRows)(src, srcStride, dst, dstStride, w, h);
}
void finishRows() { HWY_DYNAMIC_DISPATCH(FinishRows)(); }
}  // namespace darkroom::embree
#endif
