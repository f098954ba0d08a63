#include <darkroom/core/process_group.h>

#include <darkroom/error.h>

#include <algorithm>
#include <sstream>

namespace darkroom {

ProcessGroup::~ProcessGroup() = default;
WorkQueue::~WorkQueue() = default;

namespace {

// Items rank, rank + size, rank + 2 size, ...: for one process, all in order.
class StridedQueue final : public WorkQueue {
public:
    StridedQueue(std::size_t count, int rank, int size) : count_(count), next_(std::size_t(rank)), step_(std::size_t(size)) {}
    std::optional<std::size_t> next() override {
        if (failed_ || next_ >= count_) return std::nullopt;
        const std::size_t i = next_;
        next_ += step_;
        return i;
    }
    void finished() override { ++finished_; }
    void failed() override { failed_ = true; }
    std::size_t finishedEverywhere() override { return finished_; }

private:
    std::size_t count_, next_, step_, finished_ = 0;
    bool failed_ = false;
};

}  // namespace

std::unique_ptr<WorkQueue> ProcessGroup::workQueue(std::size_t count) {
    return std::make_unique<StridedQueue>(count, rank(), size());
}

void ProcessGroup::broadcast(std::string& text) {
    const std::vector<std::string> all = allGather(lead() ? text : std::string());
    text = all.front();
}

std::string ProcessGroup::agreedError(const std::string& mine) {
    const std::vector<std::string> all = allGather(mine);
    for (std::size_t r = 0; r < all.size(); ++r) {
        if (all[r].empty()) continue;
        const bool everywhere = std::all_of(all.begin(), all.end(), [&](const std::string& s) { return s == all[r]; });
        return everywhere || all.size() == 1 ? all[r] : "rank " + std::to_string(r) + ": " + all[r];
    }
    return {};
}

std::vector<std::uint64_t> ProcessGroup::exclusiveSums(const std::vector<std::uint64_t>& counts) {
    std::string mine;
    for (const std::uint64_t c : counts) mine += std::to_string(c) + " ";
    const std::vector<std::string> all = allGather(mine);
    std::vector<std::uint64_t> before(counts.size(), 0);
    for (int r = 0; r < rank(); ++r) {
        std::istringstream in(all[std::size_t(r)]);
        std::uint64_t c = 0;
        for (std::size_t i = 0; i < before.size() && in >> c; ++i) before[i] += c;
    }
    return before;
}

BufferPtr ProcessGroup::compositeByDepth(const Buffer& local, const std::vector<std::uint64_t>&, bool keepObjectId,
                                         bool keepPrimitiveId) {
    if (size() > 1)
        throw Error("compositing by depth over " + std::to_string(size()) +
                    " processes needs a process group that implements it (darkroom_mpi's)");
    auto out = makeHostBuffer(local.width(), local.height());
    out->metadata() = local.metadata();
    for (const auto& c : local.channels()) {
        if ((c.name == "objectId" && !keepObjectId) || (c.name == "primitiveId" && !keepPrimitiveId)) continue;
        out->setPlane(c, local.plane(c.name));
    }
    return out;
}

}  // namespace darkroom
