#pragma once
// Hands out the entries of a `darkroom run --foreach` to the processes of
// the run and brings their records together (docs/scale-out.md, "Batch
// shading"). Alone, entries go in order; under mpirun each rank takes the
// next entry when it has finished its last one (a shared counter on rank 0,
// MPI RMA), so ranks that draw expensive entries take fewer of them.
#include <cstddef>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace darkroom::cli {

class EntryScheduler {
public:
    virtual ~EntryScheduler();
    // The process that draws the progress bar and writes the index.
    virtual bool root() const = 0;
    // Makes root's `text` every process's (collective).
    virtual void share(std::string& text) = 0;
    // Starts handing out `count` entries (collective).
    virtual void start(std::size_t count) = 0;
    // The next entry for this process; none when all are taken or a process failed.
    virtual std::optional<std::size_t> next() = 0;
    virtual void finished() = 0;  // this process finished an entry
    virtual void failed() = 0;    // this process failed: the others stop taking entries
    // Entries finished by all processes so far.
    virtual std::size_t finishedEverywhere() = 0;
    // Every process's `mine`, in rank order, on the root (collective; empty
    // elsewhere); `anyFailed` is set on every process.
    virtual std::vector<std::string> gather(const std::string& mine, bool failedHere, bool& anyFailed) = 0;
};

class SerialEntryScheduler final : public EntryScheduler {
public:
    bool root() const override { return true; }
    void share(std::string&) override {}
    void start(std::size_t count) override { count_ = count; }
    std::optional<std::size_t> next() override;
    void finished() override { ++finished_; }
    void failed() override { failed_ = true; }
    std::size_t finishedEverywhere() override { return finished_; }
    std::vector<std::string> gather(const std::string& mine, bool failedHere, bool& anyFailed) override;

private:
    std::size_t count_ = 0, next_ = 0, finished_ = 0;
    bool failed_ = false;
};

// Alone: a SerialEntryScheduler; under mpirun: the MPI one (mpi_entry_scheduler.cpp).
std::unique_ptr<EntryScheduler> makeEntryScheduler();

}  // namespace darkroom::cli
