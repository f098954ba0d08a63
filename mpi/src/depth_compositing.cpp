// Sort-last depth compositing: binary swap (with folding for rank counts
// that are not powers of two) and an MPI_Reduce baseline. See
// depth_compositing.h for the rule and docs/scale-out.md for the costs.
#include <darkroom/error.h>
#include <darkroom/layers.h>
#include <darkroom/mpi/depth_compositing.h>

#include <algorithm>
#include <bit>
#include <climits>
#include <cstring>
#include <limits>

namespace darkroom::mpi {

const char* toString(CompositeAlgorithm a) {
    switch (a) {
        case CompositeAlgorithm::BinarySwap: return "binary-swap";
        case CompositeAlgorithm::Reduce: return "reduce";
    }
    return "?";
}

namespace {

// The id channels that break ties in depth, when the G-buffer has both.
struct IdChannels {
    bool present = false;
    std::size_t object = 0, primitive = 0;
};

IdChannels idChannels(const GBufferImage& g) {
    const int o = g.channelIndex("objectId"), p = g.channelIndex("primitiveId");
    if (o < 0 || p < 0 || g.channels[std::size_t(o)].type != ChannelType::UInt32 ||
        g.channels[std::size_t(p)].type != ChannelType::UInt32)
        return {};
    return {true, std::size_t(o), std::size_t(p)};
}

std::uint64_t idKey(const std::uint32_t* object, const std::uint32_t* primitive, std::size_t i) {
    return std::uint64_t(object[i]) << 32 | primitive[i];
}

constexpr int kFoldTag = 7101;
constexpr int kSwapTag = 7102;

std::string layoutOf(const GBufferImage& image) {
    std::string s = std::to_string(image.width) + "x" + std::to_string(image.height) + " [";
    for (std::size_t c = 0; c < image.channels.size(); ++c)
        s += (c ? ", " : "") + image.channels[c].name + ":" + toString(image.channels[c].type);
    return s + "]";
}

void checkLayouts(const Communicator& comm, const GBufferImage& image) {
    if (image.planes.size() != image.channels.size())
        throw Error("depth compositing: the image has " + std::to_string(image.channels.size()) + " channels but " +
                    std::to_string(image.planes.size()) + " planes");
    for (const auto& p : image.planes)
        if (p.size() != image.pixelCount())
            throw Error("depth compositing: a plane has " + std::to_string(p.size()) + " values, expected " +
                        std::to_string(image.pixelCount()));
    const std::vector<std::string> all = comm.allGather(layoutOf(image));
    for (int r = 1; r < comm.size(); ++r)
        if (all[std::size_t(r)] != all[0])
            throw Error("depth compositing: rank " + std::to_string(r) + " holds a G-buffer " + all[std::size_t(r)] +
                        " but rank 0 holds " + all[0] + "; every rank must render the same channels at the same size");
    // Compositing keeps each pixel's nearest record whole; the crossings
    // behind it (layer1.Z, ...) would have to be merged across ranks by
    // depth instead, which is not done yet. Every rank holds the same layout
    // (checked above), so every rank refuses alike.
    if (image.channelIndex(layers::channel("Z", 1)) >= 0)
        throw Error("depth compositing: the G-buffer " + all[0] + " holds several surface crossings per pixel "
                    "(channels: {layers: K > 1}), which compositing across ranks does not merge yet; capture "
                    "with layers: 1, or in one process (a time series can share whole steps among the ranks: "
                    "series: {ranks: steps})");
    const int z = image.channelIndex("Z");
    if (z < 0 || image.channels[std::size_t(z)].type != ChannelType::Float32)
        throw Error("depth compositing: the G-buffer " + all[0] + " has no float channel 'Z' to compare depths by");
    if (image.pixelCount() * image.channels.size() > std::size_t(INT_MAX))
        throw Error("depth compositing: " + all[0] + " has more than 2^31 values; composite smaller images");
}

// The pixels [first, first + count) of every channel, one channel after the
// other, in `out`. Packed by hand: OpenMPI moves a contiguous buffer through
// shared memory an order of magnitude faster than the same bytes described
// by an indexed datatype over separate planes (measured: bench_depth_compositing,
// 512 x 512 with 5 channels over 2 ranks, 177 ms with the datatype).
void pack(const GBufferImage& image, std::size_t first, std::size_t count, std::vector<std::uint32_t>& out) {
    out.resize(count * image.planes.size());
    for (std::size_t c = 0; c < image.planes.size(); ++c)
        std::memcpy(out.data() + c * count, image.planes[c].data() + first, count * 4);
}

bool binarySwap(const Communicator& comm, GBufferImage& image, int root, CompositeStats& stats) {
    const int P = comm.size(), r = comm.rank();
    const std::size_t n = image.pixelCount(), nch = image.channels.size();
    MPI_Comm c = comm.handle();
    int pow2 = 1;
    while (pow2 * 2 <= P) pow2 *= 2;
    const int extra = P - pow2;
    std::vector<std::uint32_t> received, sending;

    // Fold: ranks 2i+1 (i < extra) hand their whole image to 2i and sit out.
    int v = -1;  // index among the pow2 ranks that swap; -1 = folded away
    if (r < 2 * extra) {
        if (r % 2 == 1) {
            double t = MPI_Wtime();
            pack(image, 0, n, sending);
            check(MPI_Send(sending.data(), int(n * nch), MPI_UINT32_T, r - 1, kFoldTag, c), "MPI_Send");
            stats.exchangeSeconds += MPI_Wtime() - t;
            stats.bytesSent += n * nch * 4;
        } else {
            double t = MPI_Wtime();
            received.resize(n * nch);
            check(MPI_Recv(received.data(), int(n * nch), MPI_UINT32_T, r + 1, kFoldTag, c, MPI_STATUS_IGNORE),
                  "MPI_Recv");
            stats.exchangeSeconds += MPI_Wtime() - t;
            t = MPI_Wtime();
            mergeNearest(image, 0, n, received.data(), false);
            stats.mergeSeconds += MPI_Wtime() - t;
            v = r / 2;
        }
    } else {
        v = r - extra;
    }
    auto rankOf = [extra](int virtualRank) { return virtualRank < extra ? 2 * virtualRank : virtualRank + extra; };

    // Swap: partners differ in one bit, lowest first, so every group that has
    // been merged is a contiguous range of ranks and the partner's group lies
    // wholly below or above ours.
    std::size_t lo = 0, hi = n;
    if (v >= 0) {
        for (int bit = 1; bit < pow2; bit *= 2) {
            const int pv = v ^ bit;
            const bool partnerLower = pv < v;
            const std::size_t mid = lo + (hi - lo) / 2;
            const std::size_t keepLo = partnerLower ? mid : lo, keepHi = partnerLower ? hi : mid;
            const std::size_t giveLo = partnerLower ? lo : mid, giveHi = partnerLower ? mid : hi;
            const std::size_t keep = keepHi - keepLo, give = giveHi - giveLo;
            double t = MPI_Wtime();
            received.resize(keep * nch);
            pack(image, giveLo, give, sending);
            check(MPI_Sendrecv(sending.data(), int(give * nch), MPI_UINT32_T, rankOf(pv), kSwapTag, received.data(),
                               int(keep * nch), MPI_UINT32_T, rankOf(pv), kSwapTag, c, MPI_STATUS_IGNORE),
                  "MPI_Sendrecv");
            stats.exchangeSeconds += MPI_Wtime() - t;
            stats.bytesSent += give * nch * 4;
            t = MPI_Wtime();
            mergeNearest(image, keepLo, keep, received.data(), partnerLower);
            stats.mergeSeconds += MPI_Wtime() - t;
            lo = keepLo;
            hi = keepHi;
        }
    } else {
        lo = hi = 0;  // owns nothing
    }

    // Gather the pieces at the root.
    const double t = MPI_Wtime();
    unsigned long long mine[2] = {lo, hi - lo};
    std::vector<unsigned long long> pieces(r == root ? 2 * std::size_t(P) : 0);
    check(MPI_Gather(mine, 2, MPI_UNSIGNED_LONG_LONG, pieces.data(), 2, MPI_UNSIGNED_LONG_LONG, root, c), "MPI_Gather");
    std::vector<int> counts, displacements;
    if (r == root) {
        int offset = 0;
        for (int k = 0; k < P; ++k) {
            counts.push_back(int(pieces[2 * std::size_t(k) + 1] * nch));
            displacements.push_back(offset);
            offset += counts.back();
        }
        received.resize(std::size_t(offset));
    }
    pack(image, lo, hi - lo, sending);
    check(MPI_Gatherv(sending.data(), int((hi - lo) * nch), MPI_UINT32_T, received.data(), counts.data(),
                      displacements.data(), MPI_UINT32_T, root, c),
          "MPI_Gatherv");
    if (r != root) stats.bytesSent += (hi - lo) * nch * 4;
    if (r == root) {
        for (int k = 0; k < P; ++k) {
            const std::size_t first = pieces[2 * std::size_t(k)], count = pieces[2 * std::size_t(k) + 1];
            const std::uint32_t* src = received.data() + displacements[std::size_t(k)];
            for (std::size_t ch = 0; ch < nch; ++ch)
                std::memcpy(image.planes[ch].data() + first, src + ch * count, count * 4);
        }
    }
    stats.gatherSeconds += MPI_Wtime() - t;
    return r == root;
}

// MPI_Reduce operators on records [Z, other channels...] and [Z, objectId,
// primitiveId, other channels...]: the nearer record wins, at equal depth the
// lower ids (second form), then the left operand (`in`, from lower ranks).
// The record length comes from the datatype.
template <bool withIds>
void nearestRecord(void* in, void* inout, int* len, MPI_Datatype* type) {
    int bytes = 0;
    MPI_Type_size(*type, &bytes);
    const std::size_t k = std::size_t(bytes) / 4;
    const auto* a = static_cast<const std::uint32_t*>(in);
    auto* b = static_cast<std::uint32_t*>(inout);
    for (std::size_t i = 0, n = std::size_t(*len); i < n; ++i, a += k, b += k) {
        const float za = std::bit_cast<float>(a[0]), zb = std::bit_cast<float>(b[0]);
        bool left = za < zb;
        if (za == zb) left = !withIds || idKey(a + 1, a + 2, 0) <= idKey(b + 1, b + 2, 0);
        if (left) std::memcpy(b, a, k * 4);
    }
}

bool reduce(const Communicator& comm, GBufferImage& image, int root, CompositeStats& stats) {
    const std::size_t n = image.pixelCount(), nch = image.channels.size();
    const std::size_t z = std::size_t(image.channelIndex("Z"));
    // Record layout: Z first, then the ids if present, then the other channels in order.
    const IdChannels ids = idChannels(image);
    std::vector<std::size_t> order{z};
    if (ids.present) order.insert(order.end(), {ids.object, ids.primitive});
    for (std::size_t c = 0; c < nch; ++c)
        if (std::find(order.begin(), order.end(), c) == order.end()) order.push_back(c);
    double t = MPI_Wtime();
    std::vector<std::uint32_t> records(n * nch), result(comm.rank() == root ? n * nch : 0);
    for (std::size_t k = 0; k < nch; ++k) {
        const std::uint32_t* src = image.planes[order[k]].data();
        for (std::size_t i = 0; i < n; ++i) records[i * nch + k] = src[i];
    }
    stats.mergeSeconds += MPI_Wtime() - t;
    MPI_Datatype record;
    check(MPI_Type_contiguous(int(nch), MPI_UINT32_T, &record), "MPI_Type_contiguous");
    MPI_Type_commit(&record);
    MPI_Op op;
    check(MPI_Op_create(ids.present ? &nearestRecord<true> : &nearestRecord<false>,
                        0 /* not commutative: full ties go to the lower rank */, &op),
          "MPI_Op_create");
    t = MPI_Wtime();
    const int code = MPI_Reduce(records.data(), result.data(), int(n), record, op, root, comm.handle());
    stats.exchangeSeconds += MPI_Wtime() - t;
    MPI_Op_free(&op);
    MPI_Type_free(&record);
    check(code, "MPI_Reduce");
    stats.bytesSent += comm.rank() == root ? 0 : n * nch * 4;
    if (comm.rank() != root) return false;
    t = MPI_Wtime();
    for (std::size_t k = 0; k < nch; ++k) {
        std::uint32_t* dst = image.planes[order[k]].data();
        for (std::size_t i = 0; i < n; ++i) dst[i] = result[i * nch + k];
    }
    stats.mergeSeconds += MPI_Wtime() - t;
    return true;
}

}  // namespace

std::size_t mergeNearest(GBufferImage& mine, std::size_t first, std::size_t count, const std::uint32_t* other,
                         bool otherIsLower) {
    const int zc = mine.channelIndex("Z");
    if (zc < 0) throw Error("depth compositing: the G-buffer has no channel 'Z'");
    const std::uint32_t* oz = other + std::size_t(zc) * count;
    const std::uint32_t* mz = mine.planes[std::size_t(zc)].data() + first;
    const IdChannels ids = idChannels(mine);
    constexpr float kInf = std::numeric_limits<float>::infinity();
    // All ones where `other` wins. Branch-free first pass (the hits of two
    // ranks interleave unpredictably); equal depths, rarer, in a second one.
    thread_local std::vector<std::uint32_t> take;
    take.resize(count);
    std::size_t ties = 0;
    for (std::size_t i = 0; i < count; ++i) {
        const float a = std::bit_cast<float>(oz[i]), b = std::bit_cast<float>(mz[i]);
        take[i] = 0u - std::uint32_t(a < b);
        // Background on both sides holds the same miss values: nothing to copy.
        ties += std::size_t((a == b) & (a != kInf));
    }
    if (ties > 0)
        for (std::size_t i = 0; i < count; ++i) {
            const float a = std::bit_cast<float>(oz[i]), b = std::bit_cast<float>(mz[i]);
            if (!(a == b) || a == kInf) continue;
            bool t = otherIsLower;
            if (ids.present) {
                const std::uint64_t ka = idKey(other + ids.object * count, other + ids.primitive * count, i);
                const std::uint64_t kb = idKey(mine.planes[ids.object].data() + first,
                                               mine.planes[ids.primitive].data() + first, i);
                t = ka < kb || (ka == kb && otherIsLower);
            }
            take[i] = 0u - std::uint32_t(t);
        }
    std::size_t taken = 0;
    for (std::size_t i = 0; i < count; ++i) taken += take[i] & 1u;
    if (taken == 0) return 0;
    for (std::size_t c = 0; c < mine.planes.size(); ++c) {
        std::uint32_t* dst = mine.planes[c].data() + first;
        const std::uint32_t* src = other + c * count;
        for (std::size_t i = 0; i < count; ++i) dst[i] = (src[i] & take[i]) | (dst[i] & ~take[i]);
    }
    return taken;
}

bool compositeByDepth(const Communicator& comm, GBufferImage& image, const CompositeOptions& options,
                      CompositeStats* stats) {
    if (options.root < 0 || options.root >= comm.size())
        throw Error("depth compositing: root rank " + std::to_string(options.root) + " is not in the communicator of " +
                    std::to_string(comm.size()) + " ranks");
    checkLayouts(comm, image);
    CompositeStats local;
    CompositeStats& s = stats ? *stats : local;
    if (comm.size() == 1) return true;
    switch (options.algorithm) {
        case CompositeAlgorithm::BinarySwap: return binarySwap(comm, image, options.root, s);
        case CompositeAlgorithm::Reduce: return reduce(comm, image, options.root, s);
    }
    return false;
}

}  // namespace darkroom::mpi
