#include "batch_lanes.h"

#include "entry_ports.h"

#include <darkroom/error.h>

#include <algorithm>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <thread>

namespace darkroom::workflows::batch {

int lanesFor(const Graph& g, const BatchSettings& settings, const ProcessGroup& group) {
    if (group.size() > 1) return 1;
    for (const Node& node : g.nodes())
        if (writesADatabaseThroughAnEdge(g, node)) return 1;
    return settings.inFlight > 0 ? settings.inFlight : kAutomaticLanes;
}

int writerIndex(const ProcessGroup& group, int lane, int lanes) { return group.rank() * lanes + lane; }

namespace {

// What the lanes of one process share: the work queue (the group's, taken
// one lane at a time), the progress of the entries in flight, the records of
// what was shaded and the first failure.
class LaneState {
public:
    LaneState(ProcessGroup& group, std::size_t count, std::size_t kept, std::size_t total, int lanes,
              const BatchCallbacks& cb)
        : queue_(group.workQueue(count)), lead_(group.lead()), kept_(kept), total_(double(total)),
          inFlight_(std::size_t(lanes), 0.0), shaded_(std::size_t(lanes), 0), cb_(cb) {}

    std::optional<std::size_t> next() {
        std::lock_guard<std::mutex> lock(mutex_);
        if (stopped_) return std::nullopt;
        return queue_->next();
    }
    // Entry `position` of lane `lane` is done.
    void finished(int lane, std::size_t position) {
        std::lock_guard<std::mutex> lock(mutex_);
        queue_->finished();
        inFlight_[std::size_t(lane)] = 0;
        ++shaded_[std::size_t(lane)];
        records_ += std::to_string(position) + "\n";
    }
    // Every lane stops taking entries; the first failure is kept.
    void fail(std::exception_ptr e) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!failure_ && e) failure_ = e;
        if (!stopped_) queue_->failed();
        stopped_ = true;
    }
    void cancel() {
        std::lock_guard<std::mutex> lock(mutex_);
        cancelled_ = true;
        if (!stopped_) queue_->failed();
        stopped_ = true;
        for (Evaluator* e : evaluators_) e->cancel();
    }
    // Evaluators a cancel stops mid-entry: the lanes' own. The caller's
    // finishes its entry, so that its cancel flag is not left set for its
    // next evaluation.
    void add(Evaluator& e) {
        std::lock_guard<std::mutex> lock(mutex_);
        evaluators_.push_back(&e);
    }
    // On the lead: lane `lane` is `fraction` through `entry`; the whole is
    // every process's finished entries and this process's lanes in flight.
    void progress(int lane, double fraction, const std::string& entry) {
        if (!cb_.progress || !lead_) return;
        std::lock_guard<std::mutex> lock(mutex_);
        inFlight_[std::size_t(lane)] = fraction;
        double done = double(kept_ + queue_->finishedEverywhere());
        for (double f : inFlight_) done += f;
        cb_.progress(std::min(1.0, done / total_), entry);
    }
    bool cancelled() const {
        std::lock_guard<std::mutex> lock(mutex_);
        return cancelled_;
    }
    std::string records() const { return records_; }
    std::vector<std::size_t> shadedPerLane() const { return shaded_; }
    std::exception_ptr failure() const { return failure_; }

private:
    mutable std::mutex mutex_;
    std::unique_ptr<WorkQueue> queue_;
    bool lead_;
    std::size_t kept_;
    double total_;
    std::vector<double> inFlight_;
    std::vector<std::size_t> shaded_;
    const BatchCallbacks& cb_;
    std::vector<Evaluator*> evaluators_;
    std::string records_;
    std::exception_ptr failure_;
    bool stopped_ = false, cancelled_ = false;
};

struct Lane {
    int index = 0;
    Graph graph;
    EvaluatorOptions options;
    Evaluator* evaluator = nullptr;
    std::unique_ptr<Evaluator> owned;
};

// Evaluates entry `position` in lane `lane`; false when it failed or was cancelled.
bool shadeEntry(Lane& lane, std::size_t position, const BatchSettings& s, const Plan& p, const BatchCallbacks& cb,
                EvaluatorOptions o, LaneState& state) {
    const std::size_t row = p.rows[position];
    const std::string entry = p.entryName(row);
    lane.graph.setParameter(s.reader, kEntryPort, Value(std::int64_t(row)));
    for (const auto& out : p.outputs)
        lane.graph.setParameter(out.node, out.port, Value(perEntryPath(out.original, entry, *p.db, row)));
    state.progress(lane.index, 0, entry);
    o.onProgress = [&state, &lane, entry](double f, const std::string&) { state.progress(lane.index, f, entry); };
    lane.evaluator->setOptions(o);
    try {
        cb.evaluate(*lane.evaluator, lane.graph,
                    "entry " + entry + " (" + std::to_string(position + 1) + " of " + std::to_string(p.rows.size()) + ")",
                    p.entrySinks);
        return true;
    } catch (const Cancelled&) {
        state.cancel();
    } catch (const GraphError&) {
        state.fail(std::current_exception());
    } catch (const Error& e) {
        state.fail(std::make_exception_ptr(Error("entry " + entry + ": " + e.what(), e.node())));
    }
    return false;
}

// One lane: entries from the queue until none is left or a lane failed, as
// one sequence of the lane's evaluator. `afterFirst`, when given, is called
// once the first entry is shaded (the other lanes start then).
void runLane(Lane& lane, const BatchSettings& s, const Plan& p, const std::vector<std::size_t>& todo,
             const BatchCallbacks& cb, std::size_t sequenceLength, const Evaluator& caller,
             LaneState& state, const std::function<void()>& afterFirst) {
    EvaluatorSequence sequence(*lane.evaluator, SequenceInfo{sequenceLength});
    bool ok = true;
    for (bool first = true; ok; first = false) {
        // The caller's cancel (Evaluator::cancel) reaches every lane.
        if (caller.isCancelled()) state.cancel();
        const auto next = state.next();  // an index into todo
        if (!next) break;
        const std::size_t position = todo[*next];
        ok = shadeEntry(lane, position, s, p, cb, lane.options, state);
        if (ok) state.finished(lane.index, position);
        if (ok && first && afterFirst) afterFirst();
    }
    if (!ok || state.failure() || state.cancelled()) return;  // the sequence ends as not completed
    try {
        sequence.end();
    } catch (const Error&) {
        state.fail(std::current_exception());
    }
}

// The warnings of the lanes, passed on one at a time. A filter that warns
// once per sequence (a camera-less SSAO) warns once in each lane, where a
// serial run warns once; a warning given at every entry comes once per
// entry either way. Every warning's first giving is passed on at once; its
// later givings are held until the lanes end, and passed on (for the count
// of repeats) unless it was given once per lane although some lane shaded
// several entries: then it was the same once-per-sequence warning.
class LaneWarnings {
public:
    explicit LaneWarnings(std::function<void(const Diagnostic&)> report) : report_(std::move(report)) {}
    void give(int lane, const Diagnostic& d) {
        std::lock_guard<std::mutex> lock(mutex_);
        Given& g = given_[d.where + '\n' + d.message];
        ++g.perLane[lane];
        if (g.held == 0 && g.perLane.size() == 1 && g.perLane[lane] == 1) {
            report_(d);
            g.first = d;
            return;
        }
        ++g.held;
    }
    // After every lane has ended; `entries`: the entries each lane shaded.
    void finish(const std::vector<std::size_t>& entries) {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& [text, g] : given_) {
            bool oncePerLane = true, aLaneShadedMore = false;
            for (const auto& [lane, count] : g.perLane) {
                oncePerLane = oncePerLane && count == 1;
                aLaneShadedMore = aLaneShadedMore || entries[std::size_t(lane)] > 1;
            }
            if (oncePerLane && aLaneShadedMore) continue;
            for (std::size_t k = 0; k < g.held; ++k) report_(g.first);
        }
    }

private:
    struct Given {
        std::map<int, std::size_t> perLane;  // givings per lane
        std::size_t held = 0;                // givings not passed on yet
        Diagnostic first;
    };
    std::mutex mutex_;
    std::function<void(const Diagnostic&)> report_;
    std::map<std::string, Given> given_;
};

// The evaluator options of lane `lane`: a share of the cache, its warnings
// through `warnings`.
EvaluatorOptions laneOptions(const EvaluatorOptions& options, int lane, int lanes, LaneWarnings* warnings) {
    EvaluatorOptions o = options;
    if (lanes == 1) return o;
    o.cacheBytes = options.cacheBytes / std::size_t(lanes);
    if (warnings) o.onWarning = [warnings, lane](const Diagnostic& d) { warnings->give(lane, d); };
    return o;
}

// The lanes' graphs: copies of `graph`. When the plan stages, each database
// sink writes into the lane's staging database, but in lane 0 of a lone
// process, which writes the database itself, in the node's own mode.
std::vector<Lane> makeLanes(const Graph& graph, Evaluator& evaluator, const Plan& p, ProcessGroup& group, int lanes,
                            LaneWarnings* warnings) {
    std::vector<Lane> out;
    out.reserve(std::size_t(lanes));
    for (int k = 0; k < lanes; ++k) {
        Lane& lane = out.emplace_back(Lane{k, graph, laneOptions(p.options, k, lanes, warnings), nullptr, nullptr});
        for (const auto& d : p.databases) {
            if (!p.staging || (k == 0 && p.firstLaneInPlace)) break;
            lane.graph.setParameter(d.node, d.port, Value(stagingDatabase(d, writerIndex(group, k, lanes))));
            lane.graph.setParameter(d.node, "mode", Value(std::string("overwrite")));
        }
        if (k == 0) {
            lane.evaluator = &evaluator;
        } else {
            lane.owned = std::make_unique<Evaluator>(lane.options);
            lane.evaluator = lane.owned.get();
        }
    }
    return out;
}

}  // namespace

std::string shadeOverLanes(const Graph& graph, Evaluator& evaluator, const BatchSettings& settings, const Plan& p,
                           const std::vector<std::size_t>& todo, ProcessGroup& group, const BatchCallbacks& cb,
                           int lanes, std::exception_ptr& failure) {
    std::optional<LaneWarnings> warnings;
    if (p.options.onWarning) warnings.emplace(p.options.onWarning);
    std::vector<Lane> all = makeLanes(graph, evaluator, p, group, lanes, warnings ? &*warnings : nullptr);
    LaneState state(group, todo.size(), p.rows.size() - todo.size(), p.rows.size(), lanes, cb);
    for (auto& lane : all)
        if (lane.owned) state.add(*lane.owned);
    // Only a lone lane of a lone process knows how many entries its sequence holds.
    const std::size_t length = lanes == 1 && group.size() == 1 ? todo.size() : 0;
    const auto run = [&](Lane& lane, const std::function<void()>& afterFirst) {
        runLane(lane, settings, p, todo, cb, length, evaluator, state, afterFirst);
    };
    {
        // Lane 0 shades the first entry alone: what a serial run refuses at
        // its first entry (a resume with other writer settings) is refused
        // before any other lane has shaded, and what the first entry makes
        // for every later one (a database range, plugins loaded) is made once.
        std::vector<std::jthread> threads;
        const auto startOthers = [&] {
            for (std::size_t k = 1; k < all.size(); ++k) threads.emplace_back([&run, &all, k] { run(all[k], {}); });
        };
        run(all[0], startOthers);  // on the calling thread: under mpirun, the only lane, and the group's calls stay on it
    }
    if (warnings) warnings->finish(state.shadedPerLane());
    // Lane 0's evaluator is the caller's: its options go back as they were.
    evaluator.setOptions(p.options);
    if (state.cancelled()) throw Cancelled();
    failure = state.failure();
    return state.records();
}

}  // namespace darkroom::workflows::batch
