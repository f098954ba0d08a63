#include <darkroom/error.h>
#include <darkroom/mpi/distributed_capture.h>

#include <algorithm>
#include <cstring>

namespace darkroom::mpi {

namespace {

constexpr std::uint32_t kNoId = 0xFFFFFFFFu;

void removeChannel(GBufferImage& image, const std::string& name) {
    const int c = image.channelIndex(name);
    if (c < 0) return;
    image.channels.erase(image.channels.begin() + c);
    image.planes.erase(image.planes.begin() + c);
}

}  // namespace

std::shared_ptr<WritableBuffer> compositeCapture(const Communicator& comm, const Buffer& local,
                                                 const std::vector<std::uint64_t>& primitiveOffsets,
                                                 bool keepObjectId, bool keepPrimitiveId, CompositeStats* stats) {
    GBufferImage image = GBufferImage::from(local);
    const std::uint32_t* object = image.uintPlane("objectId");
    std::uint32_t* primitive = image.uintPlane("primitiveId");
    if (!object || !primitive)
        throw Error("distributed capture: the G-buffer lacks objectId or primitiveId, which break ties in depth");
    for (std::size_t i = 0, n = image.pixelCount(); i < n; ++i) {
        if (object[i] == kNoId) continue;
        if (object[i] >= primitiveOffsets.size())
            throw Error("distributed capture: a pixel hit object " + std::to_string(object[i]) + " of " +
                        std::to_string(primitiveOffsets.size()));
        primitive[i] = std::uint32_t(primitive[i] + primitiveOffsets[object[i]]);
    }
    if (!compositeByDepth(comm, image, {}, stats)) return nullptr;
    if (!keepObjectId) removeChannel(image, "objectId");
    if (!keepPrimitiveId) removeChannel(image, "primitiveId");
    return image.toBuffer();
}

std::string agreedError(const Communicator& comm, const std::string& mine) {
    const auto all = comm.allGather(mine);
    for (std::size_t r = 0; r < all.size(); ++r) {
        if (all[r].empty()) continue;
        const bool everywhere = std::all_of(all.begin(), all.end(), [&](const std::string& s) { return s == all[r]; });
        return everywhere || all.size() == 1 ? all[r] : "rank " + std::to_string(r) + ": " + all[r];
    }
    return {};
}

std::vector<std::uint64_t> exclusiveSums(const Communicator& comm, const std::vector<std::uint64_t>& counts) {
    std::vector<std::uint64_t> before(counts.size(), 0);
    if (counts.empty()) return before;
    check(MPI_Exscan(counts.data(), before.data(), int(counts.size()), MPI_UINT64_T, MPI_SUM, comm.handle()),
          "MPI_Exscan");
    if (comm.rank() == 0) std::fill(before.begin(), before.end(), 0);  // MPI leaves rank 0's result undefined
    return before;
}

}  // namespace darkroom::mpi
