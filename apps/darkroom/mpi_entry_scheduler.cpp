// Entries of a --foreach run over MPI ranks: dynamic self-scheduling on
// shared counters held by rank 0 (darkroom::mpi::SharedCounters).
#include "entry_scheduler.h"
#include "processes.h"

#include <darkroom/mpi/shared_counters.h>

namespace darkroom::cli {

namespace {

enum Counter : int { kNext = 0, kFinished = 1, kFailed = 2, kCounters = 3 };

class MpiEntryScheduler final : public EntryScheduler {
public:
    MpiEntryScheduler() : comm_(MPI_COMM_WORLD) {}
    bool root() const override { return comm_.rank() == 0; }
    void share(std::string& text) override { comm_.broadcast(text); }
    void start(std::size_t count) override {
        count_ = count;
        counters_ = std::make_unique<mpi::SharedCounters>(comm_, kCounters);
    }
    std::optional<std::size_t> next() override {
        if (counters_->read(kFailed) > 0) return std::nullopt;
        const std::int64_t i = counters_->fetchAdd(kNext);
        if (i < 0 || std::size_t(i) >= count_) return std::nullopt;
        return std::size_t(i);
    }
    void finished() override { counters_->fetchAdd(kFinished); }
    void failed() override { counters_->fetchAdd(kFailed); }
    std::size_t finishedEverywhere() override { return std::size_t(counters_->read(kFinished)); }
    std::vector<std::string> gather(const std::string& mine, bool failedHere, bool& anyFailed) override {
        anyFailed = !comm_.allAgree(!failedHere);
        auto all = comm_.allGather(mine);
        counters_.reset();  // collective: every rank is here
        if (!root()) all.clear();
        return all;
    }

private:
    mpi::Communicator comm_;
    std::size_t count_ = 0;
    std::unique_ptr<mpi::SharedCounters> counters_;
};

}  // namespace

std::unique_ptr<EntryScheduler> makeEntryScheduler() {
    if (processes().size == 1) return std::make_unique<SerialEntryScheduler>();
    return std::make_unique<MpiEntryScheduler>();
}

}  // namespace darkroom::cli
