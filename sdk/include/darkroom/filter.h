#pragma once
#include <darkroom/context.h>
#include <darkroom/export.h>
#include <darkroom/port.h>

#include <cstddef>

namespace darkroom {

// How the host may call execute() concurrently.
enum class ThreadSafety : std::uint8_t {
    // Only one execute() of this filter type at a time, across all instances
    // (e.g. a library with global state).
    Unsafe,
    // Different instances may execute at the same time; one instance is never
    // entered twice at once. The default.
    InstanceSafe,
    // One instance may be entered by several threads at once (execute keeps
    // nothing in the instance, or guards it): a host may then shade several
    // entries of a batch through one instance. Today's hosts run it as
    // InstanceSafe.
    Reentrant,
};

// What the host says about a sequence: its bracket around a series of
// execute() calls, as OpenFX brackets a series of renders with its
// begin/end sequence actions. A sequence is one evaluation in the editor or
// a script, every entry one process shades in a batch (`darkroom run
// --foreach`), one capture.
struct SequenceInfo {
    // Evaluations the sequence is expected to hold (the entries a batch
    // process was given); 0 when not known.
    std::size_t length = 0;
};

// A shading pass or any other node. To add one: inherit, declare ports,
// implement execute — nothing else.
//
// The caching contract. The host keys a node's cached result on exactly what
// execute() reads, which it records as the filter runs:
//   - its value inputs (a Path input, and a ColorMap input naming a file,
//     also by the file's modification time and size);
//   - of each image input, the planes of the channels asked for through
//     hostFloat/hostUInt/requireFloat/requireUInt/plane, whether the channel
//     list (channels(), hasChannel, channelType...) or the metadata was looked
//     at, and always the size;
//   - every file named with Context::readsFile.
// Reading nothing else is the contract: the outputs must be a function of
// those, computed afresh by each execute() (keep no results between calls;
// caches of parsed files are fine when keyed by the file's stamp). A filter
// that cannot say what it reads looks at it through these calls anyway, and is
// keyed conservatively on all of it.
//
// Channels a pass merely passes on are not reads: with Context::derive (or by
// publishing an input buffer itself) the host knows which planes came from
// the input, and when only those change upstream it re-assembles the output
// around the new planes without calling execute().
class DARKROOM_API Filter {
public:
    virtual ~Filter();

    // Side-effect free. The host asks a fresh instance of each type once
    // (and once when the plugin registers, to check the declaration) and
    // keeps the answer for the session, in the registry: the ports of a type
    // are fixed, the same for every instance, never computed per call.
    virtual PortList ports() const = 0;

    // Reads inputs from the context, allocates and publishes every output.
    // Throwing darkroom::Error (or any std::exception) marks this node failed
    // with that message; the host names the node (so the message should not).
    virtual void execute(Context& ctx) = 0;

    virtual ThreadSafety threadSafety() const { return ThreadSafety::InstanceSafe; }

    // The sequence bracket. beginSequence comes before this instance's first
    // execute() of a sequence; endSequence after the sequence's last
    // evaluation (`completed` false when it stopped early: an error
    // anywhere, a cancellation), and only if beginSequence was called. A
    // filter that keeps something between executes — an open database and
    // its lock, an encoder — takes it inside the bracket and lets it go in
    // endSequence: outside a sequence it holds nothing. Never called
    // concurrently with execute() or each other. Throwing from endSequence
    // fails the sequence, naming the node. Default: nothing.
    virtual void beginSequence(const SequenceInfo& info);
    virtual void endSequence(const SequenceInfo& info, bool completed);
};

}  // namespace darkroom
