#pragma once
// The processes one piece of work spans: this process alone, the ranks of
// `mpirun -np N darkroom ...`, or a simulation's communicator in situ. The
// one abstraction over ranks that the workflows (capture, scene loading)
// talk through; the framework knows nothing of MPI (darkroom_mpi implements
// it over a communicator, mpi/include/darkroom/mpi/mpi_process_group.h).
//
// Every method but rank(), size(), lead() and onThisNode() is collective:
// every process calls it the same number of times in the same order.
#include <darkroom/buffer.h>
#include <darkroom/export.h>

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace darkroom {

// Items (the entries of a batch) handed out to the processes of a group.
// Made and destroyed collectively (ProcessGroup::workQueue); in between,
// each process takes items without waiting for the others.
class DARKROOM_API WorkQueue {
public:
    virtual ~WorkQueue();
    // The next item for this process; none when all are taken or a process failed.
    virtual std::optional<std::size_t> next() = 0;
    virtual void finished() = 0;  // this process finished its item
    virtual void failed() = 0;    // this process failed: the others stop taking items
    // Items finished by all processes so far (for progress).
    virtual std::size_t finishedEverywhere() = 0;
};

class DARKROOM_API ProcessGroup {
public:
    virtual ~ProcessGroup();
    virtual int rank() const = 0;
    virtual int size() const = 0;
    // The process that opens and writes the database: rank 0.
    bool lead() const { return rank() == 0; }
    // Processes of this group on this machine, which share its cores.
    virtual int onThisNode() const { return 1; }

    // Every process's string, in rank order, on every process.
    virtual std::vector<std::string> allGather(const std::string& mine) = 0;
    // The lead's `text` on every process. By default through allGather.
    virtual void broadcast(std::string& text);
    // The first non-empty message of any process ("rank k: ..." unless every
    // process has the same), or "" when none failed. By default through allGather.
    virtual std::string agreedError(const std::string& mine);
    // For each entry of `counts` (the same length everywhere), the sum over
    // the lower ranks. By default through allGather.
    virtual std::vector<std::uint64_t> exclusiveSums(const std::vector<std::uint64_t>& counts);
    // Composites each process's G-buffer of its part of the scene by depth:
    // `local` carries objectId and primitiveId with ids local to the part
    // (primitive id + primitiveOffsets[object] is the whole scene's). The
    // whole image on the lead, nullptr elsewhere; the id channels only when
    // kept. One process: `local` with the ids not kept dropped. More than
    // one: implemented by the group (darkroom_mpi's binary swap); the
    // default throws darkroom::Error.
    virtual BufferPtr compositeByDepth(const Buffer& local, const std::vector<std::uint64_t>& primitiveOffsets,
                                       bool keepObjectId, bool keepPrimitiveId);
    // Hands out `count` items. One process takes them in order. By default
    // several take every size()-th (a failure is known only at the end);
    // darkroom_mpi's queue is dynamic: each rank takes the next item when it
    // has finished its last, from counters on the lead, so ranks that draw
    // expensive items take fewer, and a failure stops the others' taking.
    virtual std::unique_ptr<WorkQueue> workQueue(std::size_t count);
};

// This process alone.
class DARKROOM_API SingleProcess final : public ProcessGroup {
public:
    int rank() const override { return 0; }
    int size() const override { return 1; }
    std::vector<std::string> allGather(const std::string& mine) override { return {mine}; }
};

}  // namespace darkroom
