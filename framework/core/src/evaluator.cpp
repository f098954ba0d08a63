#include "hashing.h"
#include "node_runner.h"
#include "same_bytes.h"
#include "shared_sources_impl.h"

#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cstring>
#include <functional>
#include <unordered_set>
#include <utility>

namespace darkroom {

GraphError::GraphError(Diagnostics d)
    : Error([&] {
          std::string m;
          for (const auto& x : d)
              if (x.severity == Diagnostic::Severity::Error) m += (m.empty() ? "" : "\n") + x.str();
          return m.empty() ? std::string("invalid graph") : m;
      }()),
      diagnostics_(std::move(d)) {}
GraphError::~GraphError() = default;

const char* toString(NodeProfile::Status s) {
    switch (s) {
        case NodeProfile::Status::Ran: return "ran";
        case NodeProfile::Status::Reassembled: return "reassembled";
        case NodeProfile::Status::Cached: return "cached";
    }
    return "?";
}

struct Evaluator::NodeState {
    std::unique_ptr<Filter> filter;
    std::string filterType;
    // The cache entry: valid when the node's outputs are held.
    bool valid = false;
    std::uint64_t valueKey = 0;
    std::vector<InputRead> reads;
    std::vector<FileStamp> files;
    std::vector<std::string> inputs;  // what the node read: downstream outputs must spare it
    std::map<std::string, Value> outputs;
    std::map<std::string, OutputOrigin> origins;
    std::uint64_t lastUsed = 0;
    bool begun = false;  // the filter's beginSequence was called in the open sequence
    // Statistics.
    std::uint64_t executions = 0;
    double seconds = 0;
};

struct Evaluator::Progress {
    std::mutex mutex;
    std::size_t total = 0;
    std::size_t done = 0;
};

namespace {

using Inputs = std::map<std::string, std::vector<Value>>;

// Everything a node is keyed on besides what it reads of its images: its
// type, where its paths resolve, every value input, and how many images
// each image input has.
std::uint64_t valueKey(const Node& n, const PortList& ports, const Inputs& inputs, const EvaluatorOptions& o) {
    using namespace hashing;
    std::uint64_t h = mixText(mixText(mixText(0x452821e638d01377ULL, n.type), o.inputBase), o.outputDir);
    for (const auto& in : ports.inputs) {
        h = mixText(h, in.name);
        auto it = inputs.find(in.name);
        if (in.type == PortType::Image) {
            h = mix(h, it == inputs.end() ? 0 : it->second.size());
            continue;
        }
        h = mix(h, hashValue(it == inputs.end() || it->second.empty() ? in.defaultValue : it->second.front()));
    }
    return h;
}

// A node that reads no image (a reader, a capture): what it makes depends
// only on its key and the files it read, so evaluators may share it.
bool readsNoImage(const PortList& ports, const Inputs& inputs) {
    for (const auto& in : ports.inputs)
        if (in.type == PortType::Image && inputs.count(in.name)) return false;
    return true;
}

const Buffer* imageAt(const Inputs& inputs, const std::string& port, int index) {
    auto it = inputs.find(port);
    if (it == inputs.end() || index < 0 || index >= int(it->second.size())) return nullptr;
    return it->second[std::size_t(index)].asImage().get();
}

BufferPtr imagePtrAt(const Inputs& inputs, const std::string& port, int index) {
    auto it = inputs.find(port);
    if (it == inputs.end() || index < 0 || index >= int(it->second.size())) return nullptr;
    return it->second[std::size_t(index)].asImage();
}

// Same channels, same planes (by identity) and same metadata.
bool samePlanes(const Buffer& a, const Buffer& b) {
    if (a.width() != b.width() || a.height() != b.height() || a.channels() != b.channels()) return false;
    for (const auto& c : a.channels())
        if (a.plane(c.name) != b.plane(c.name)) return false;
    return a.metadata() == b.metadata();
}

// A plane recomputed bit for bit as before keeps the previous plane, so nodes
// downstream that read it keep their cache. Returns the previous buffer
// itself when nothing at all changed.
BufferPtr keepUnchangedPlanes(const BufferPtr& fresh, const BufferPtr& previous) {
    if (!previous || previous->width() != fresh->width() || previous->height() != fresh->height()) return fresh;
    const std::size_t bytes = fresh->pixelCount() * 4;
    std::shared_ptr<WritableBuffer> merged;
    for (const auto& c : fresh->channels()) {
        const PlanePtr now = fresh->plane(c.name);
        const PlanePtr before = previous->plane(c.name);
        if (!before || before == now || previous->channelType(c.name) != c.type) continue;
        if (bytes && !sameBytes(now->data(), before->data(), bytes)) continue;
        if (!merged) {
            merged = makeHostBuffer(fresh->width(), fresh->height());
            merged->metadata() = fresh->metadata();
            for (const auto& x : fresh->channels()) merged->setPlane(x, fresh->plane(x.name));
        }
        merged->setPlane(c, before);
    }
    const BufferPtr result = merged ? BufferPtr(merged) : fresh;
    return samePlanes(*result, *previous) ? previous : result;
}

std::size_t planeBytes(const std::map<std::string, Value>& outputs, std::unordered_set<const Plane*>& seen) {
    std::size_t total = 0;
    for (const auto& [port, v] : outputs)
        if (const auto* b = std::get_if<BufferPtr>(&v.storage()); b && *b)
            for (const auto& c : (*b)->channels()) {
                const PlanePtr p = (*b)->plane(c.name);
                if (p && seen.insert(p.get()).second) total += p->pixels() * 4;
            }
    return total;
}

// The node's inputs: the upstream outputs (each up to date: it is in an
// earlier wave), else the node's parameters.
template <class States>
Inputs gatherInputs(const Graph& g, const Node& n, const PortList& ports, const States& states, std::mutex& mutex) {
    Inputs inputs;
    for (const auto& in : ports.inputs) {
        std::vector<Value> values;
        for (const auto& e : g.edgesInto(n.name, in.name)) {
            std::lock_guard<std::mutex> lock(mutex);
            const auto& up = *states.at(e.from.node);
            auto it = up.outputs.find(e.from.port);
            if (!up.valid || it == up.outputs.end())
                throw Error(nodeLabel(n.name, n.type) + ": upstream " + e.from.str() + " produced nothing", n.name);
            values.push_back(it->second);
        }
        if (values.empty() && in.type != PortType::Image)
            if (const Value* p = n.parameter(in.name)) values.push_back(*p);
        if (!values.empty()) inputs[in.name] = std::move(values);
    }
    return inputs;
}

// What every node upstream of `node` read, from their cache records: an
// output `node` resolves must not write over any of it.
template <class States>
std::vector<UpstreamInput> upstreamInputsOf(const Graph& g, const std::string& node, const States& states,
                                            std::mutex& mutex) {
    std::set<std::string> seen = g.upstreamOf({node});
    seen.erase(node);
    std::vector<UpstreamInput> out;
    std::lock_guard<std::mutex> lock(mutex);
    for (const auto& name : seen)
        if (auto it = states.find(name); it != states.end())
            for (const auto& path : it->second->inputs) out.push_back({name, path});
    return out;
}

// Whether the cached result still holds: the same value inputs, the same
// planes read, the same files. When not, `reason` says why.
template <class State>
bool cacheHolds(const State& st, const Inputs& inputs, std::uint64_t key, std::string& reason) {
    bool hit = st.valid && st.valueKey == key;
    if (!st.valid) reason = "no cached result";
    else if (!hit) reason = "a value input changed";
    for (std::size_t i = 0; hit && i < st.reads.size(); ++i) {
        const Buffer* b = imageAt(inputs, st.reads[i].port, st.reads[i].index);
        hit = b && stillMatches(st.reads[i], *b, &reason);
        if (!b) reason = "input '" + st.reads[i].port + "' is gone";
    }
    for (std::size_t i = 0; hit && i < st.files.size(); ++i) {
        hit = stampOf(st.files[i].path) == st.files[i];
        if (!hit) reason = "file changed: " + st.files[i].path;
    }
    return hit;
}

// The cached outputs around the current inputs: a forwarded output is the
// input now, a derived one the recorded fresh planes around the input's
// planes now. Also whether any output changed.
template <class State>
std::pair<std::map<std::string, Value>, bool> reassemble(const State& st, const Inputs& inputs) {
    std::map<std::string, Value> outputs = st.outputs;
    bool changed = false;
    for (auto& [port, value] : outputs) {
        const OutputOrigin& o = st.origins.at(port);
        if (o.kind == OutputOrigin::Kind::Forward) {
            BufferPtr now = imagePtrAt(inputs, o.port, o.index);
            if (now != value.asImage()) {
                value = Value(std::move(now));
                changed = true;
            }
        } else if (o.kind == OutputOrigin::Kind::Derived) {
            const Buffer* in = imageAt(inputs, o.port, o.index);
            const BufferPtr& before = value.asImage();
            BufferPtr now = rederive(o, *before, *in);
            if (!samePlanes(*now, *before)) {
                value = Value(std::move(now));
                changed = true;
            }
        }
    }
    return {std::move(outputs), changed};
}

// Fresh image outputs keep the previous planes they recomputed bit for bit.
void keepUnchangedOutputs(NodeResult& r, const std::map<std::string, Value>& previous) {
    for (auto& [port, value] : r.outputs) {
        const auto* b = std::get_if<BufferPtr>(&value.storage());
        if (!b || !*b || r.origins[port].kind == OutputOrigin::Kind::Forward) continue;
        auto it = previous.find(port);
        const auto* p = it == previous.end() ? nullptr : std::get_if<BufferPtr>(&it->second.storage());
        value = Value(keepUnchangedPlanes(*b, p ? *p : nullptr));
    }
}

// Everything is checked before anything runs.
void throwIfInvalid(const Graph& g, const std::set<std::string>& needed) {
    Diagnostics problems;
    for (auto& d : g.validate())
        if (d.severity == Diagnostic::Severity::Error && (d.node.empty() || needed.count(d.node)))
            problems.push_back(std::move(d));
    if (!problems.empty()) throw GraphError(std::move(problems));
}

// Depth levels: a node runs after everything it reads; nodes of one level
// are independent and run concurrently. In topological order every input's
// level is known before its reader's. Also counts, per node, the readers of
// its outputs among the needed nodes.
std::vector<std::vector<std::string>> wavesOf(const Graph& g, const std::set<std::string>& needed,
                                              std::map<std::string, int>& pendingReaders) {
    std::map<std::string, int> level;
    std::vector<std::vector<std::string>> waves;
    for (const auto& n : g.topologicalOrder()) {
        if (!needed.count(n)) continue;
        int d = 0;
        for (const auto& e : g.edgesInto(n)) {
            auto it = level.find(e.from.node);
            d = std::max(d, (it == level.end() ? 0 : it->second) + 1);
            ++pendingReaders[e.from.node];
        }
        level[n] = d;
        if (int(waves.size()) <= d) waves.resize(std::size_t(d) + 1);
        waves[std::size_t(d)].push_back(n);
    }
    return waves;
}

// Ends a filter's sequence; what it threw, as text ("" when nothing). A
// filter's failure here must not stop the others from letting go.
std::string endFilterSequence(Filter& filter, const SequenceInfo& info, bool completed) {
    try {
        filter.endSequence(info, completed);
    } catch (const std::exception& e) {
        return e.what();
    } catch (...) {
        return "unknown error";
    }
    return "";
}

// States dropped (their node removed or retyped, the cache cleared) whose
// filters began the open sequence are ended, as not completed, before they go.
template <class State>
void endRetired(std::vector<std::unique_ptr<State>>& retired, const SequenceInfo& info) {
    for (auto& st : retired)
        if (st && st->begun && st->filter) (void)endFilterSequence(*st->filter, info, false);
    retired.clear();
}

}  // namespace

Evaluator::Evaluator(EvaluatorOptions options) : options_(std::move(options)) {}

Evaluator::~Evaluator() {
    try {
        endSequence(false);
    } catch (...) {
    }
}

void Evaluator::setOptions(EvaluatorOptions options) {
    std::lock_guard<std::mutex> lock(mutex_);
    options_ = std::move(options);
}

std::set<std::string> Evaluator::wouldRun(const Graph& g, const std::vector<std::string>& targets) const {
    // A copy of what the cache check reads, taken under the lock.
    struct Snapshot {
        bool valid = false;
        std::uint64_t valueKey = 0;
        std::vector<InputRead> reads;
        std::vector<FileStamp> files;
    };
    const std::set<std::string> needed = g.upstreamOf(targets);
    std::set<std::string> runs;
    for (const auto& name : g.topologicalOrder()) {
        if (!needed.count(name)) continue;
        const Node& n = *g.node(name);
        bool upstreamRuns = false;
        for (const auto& e : g.edgesInto(name)) upstreamRuns = upstreamRuns || runs.count(e.from.node);
        Snapshot st;
        {
            std::lock_guard<std::mutex> lock(mutex_);
            const auto it = states_.find(name);
            if (it != states_.end() && it->second->filterType == n.type && !n.placeholder)
                st = {it->second->valid, it->second->valueKey, it->second->reads, it->second->files};
        }
        // The same tests process() makes before it runs a node: its own
        // cache, then (a source) what another evaluator shares.
        bool same = st.valid && !upstreamRuns;
        const bool mayShare = options_.sharedSources && !upstreamRuns && !n.placeholder;
        try {
            if (same || mayShare) {
                const Inputs inputs = gatherInputs(g, n, g.ports(n), states_, mutex_);
                const std::uint64_t key = valueKey(n, g.ports(n), inputs, options_);
                std::string reason;
                same = same && cacheHolds(st, inputs, key, reason);
                if (!same && mayShare && readsNoImage(g.ports(n), inputs))
                    same = options_.sharedSources->impl_->holds(key);
            }
        } catch (const std::exception&) {
            same = false;  // an input it would read is not held here: it runs
        }
        if (!same) runs.insert(name);
    }
    return runs;
}

std::uint64_t Evaluator::executions(const std::string& node) const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = states_.find(node);
    return it == states_.end() ? 0 : it->second->executions;
}

double Evaluator::lastSeconds(const std::string& node) const {
    std::lock_guard<std::mutex> lock(mutex_);
    auto it = states_.find(node);
    return it == states_.end() ? 0.0 : it->second->seconds;
}

std::vector<NodeProfile> Evaluator::lastProfile() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return profile_;
}

std::size_t Evaluator::cachedBytes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return cachedBytesLocked();
}

std::size_t Evaluator::cachedBytesLocked() const {
    std::unordered_set<const Plane*> seen;
    std::size_t total = 0;
    for (const auto& [name, st] : states_)
        if (st->valid) total += planeBytes(st->outputs, seen);
    return total;
}

void Evaluator::clearCache() {
    std::vector<std::unique_ptr<NodeState>> retired;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (auto& [name, st] : states_) retired.push_back(std::move(st));
        states_.clear();
    }
    endRetired(retired, sequence_);
}

void Evaluator::beginSequence(SequenceInfo info) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (sequenceOpen_) throw Error("a sequence is already open on this evaluator; sequences do not nest");
    sequenceOpen_ = true;
    sequence_ = info;
}

bool Evaluator::inSequence() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return sequenceOpen_;
}

void Evaluator::endSequence(bool completed) {
    std::vector<std::pair<std::string, NodeState*>> begun;
    SequenceInfo info;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!sequenceOpen_) return;
        sequenceOpen_ = false;
        info = sequence_;
        for (auto& [name, st] : states_)
            if (st->begun) {
                st->begun = false;
                begun.emplace_back(name, st.get());
            }
    }
    std::string firstFailure, failedNode;
    for (auto& [name, st] : begun) {
        const std::string failure = endFilterSequence(*st->filter, info, completed);
        if (!failedNode.empty() || failure.empty()) continue;
        firstFailure = nodeLabel(name, st->filterType) + ": " + failure;
        failedNode = name;
    }
    if (!failedNode.empty()) throw Error(firstFailure, failedNode);
}

void Evaluator::beginSequenceOf(const Node& n, NodeState& st) {
    SequenceInfo info;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        if (st.begun || !sequenceOpen_) return;
        info = sequence_;
    }
    try {
        st.filter->beginSequence(info);
    } catch (const std::exception& e) {
        throw Error(nodeLabel(n.name, n.type) + ": " + e.what(), n.name);
    }
    std::lock_guard<std::mutex> lock(mutex_);
    st.begun = true;
}

EvaluatorSequence::EvaluatorSequence(Evaluator& evaluator, SequenceInfo info) : evaluator_(&evaluator) {
    evaluator.beginSequence(info);
}

EvaluatorSequence::~EvaluatorSequence() {
    if (!evaluator_) return;
    try {
        evaluator_->endSequence(false);
    } catch (...) {
        // Already failing (or cancelled): the first failure is the one reported.
    }
}

void EvaluatorSequence::end() {
    Evaluator* e = std::exchange(evaluator_, nullptr);
    if (e) e->endSequence(true);
}

Value Evaluator::evaluate(const Graph& graph, const std::string& node, const std::string& port,
                          const std::atomic<bool>* cancel) {
    const Node* n = graph.node(node);
    if (!n) throw Error("no node named '" + node + "'");
    if (!n->placeholder && !graph.ports(*n).output(port))
        throw Error(nodeLabel(node, n->type) + " has no output '" + port + "'");
    ensure(graph, {node}, cancel);
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.at(node)->outputs.at(port);
}

BufferPtr Evaluator::evaluateImage(const Graph& graph, const std::string& node, const std::string& port,
                                   const std::atomic<bool>* cancel) {
    return evaluate(graph, node, port, cancel).asImage();
}

void Evaluator::run(const Graph& graph, std::vector<std::string> nodes, const std::atomic<bool>* cancel) {
    if (nodes.empty()) nodes = graph.sinks();
    if (nodes.empty())
        throw Error("the pipeline has no output node (a node without outputs, such as ImageWriter)");
    for (const auto& n : nodes)
        if (!graph.node(n)) throw Error("no node named '" + n + "'");
    ensure(graph, nodes, cancel);
}

void Evaluator::ensure(const Graph& g, const std::vector<std::string>& targets, const std::atomic<bool>* cancel) {
    if (inSequence()) return evaluateWaves(g, targets, cancel);
    // A sequence of its own, so no filter holds anything once this returns.
    EvaluatorSequence sequence(*this);
    evaluateWaves(g, targets, cancel);
    sequence.end();
}

void Evaluator::evaluateWaves(const Graph& g, const std::vector<std::string>& targets,
                              const std::atomic<bool>* external) {
    // The internal flag is cleared when a run ends, not when one starts, so a
    // cancel() that arrives before the run starts still cancels it.
    struct ClearOnExit {
        std::atomic<bool>* flag;
        ~ClearOnExit() {
            if (flag) *flag = false;
        }
    } clear{external ? nullptr : &cancelled_};
    const std::atomic<bool>& cancel = external ? *external : cancelled_;

    const std::set<std::string> needed = g.upstreamOf(targets);
    throwIfInvalid(g, needed);
    // Outputs still to be read in this evaluation, for retainIntermediate = false.
    std::map<std::string, int> pendingReaders;
    const std::vector<std::vector<std::string>> waves = wavesOf(g, needed, pendingReaders);
    std::vector<std::unique_ptr<NodeState>> retired;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        // States of nodes that were removed, renamed or retyped are freed.
        for (auto it = states_.begin(); it != states_.end();) {
            const Node* n = g.node(it->first);
            if (!n || n->placeholder || (it->second->filter && it->second->filterType != n->type)) {
                retired.push_back(std::move(it->second));
                it = states_.erase(it);
            } else {
                ++it;
            }
        }
        ++clock_;
        profile_.clear();
        for (const auto& n : needed)
            if (auto& st = states_[n]; !st) st = std::make_unique<NodeState>();
    }
    endRetired(retired, sequence_);
    const std::set<std::string> targetSet(targets.begin(), targets.end());

    Progress progress;
    for (const auto& w : waves) progress.total += w.size();
    progress_ = &progress;
    struct ResetProgress {
        Progress** p;
        ~ResetProgress() { *p = nullptr; }
    } resetProgress{&progress_};

    tbb::task_arena arena(options_.threads > 0 ? options_.threads : tbb::task_arena::automatic);
    for (const auto& wave : waves) {
        if (cancel) throw Cancelled();
        std::vector<std::exception_ptr> errors(wave.size());
        arena.execute([&] {
            tbb::parallel_for(std::size_t(0), wave.size(), [&](std::size_t i) {
                try {
                    const Node& n = *g.node(wave[i]);
                    NodeState* st;
                    {
                        std::lock_guard<std::mutex> lock(mutex_);
                        st = states_.at(n.name).get();
                    }
                    process(g, n, *st, cancel);
                } catch (...) {
                    errors[i] = std::current_exception();
                }
            });
        });
        // Report the first failure in graph order, so messages do not depend
        // on scheduling.
        for (auto& e : errors)
            if (e) std::rethrow_exception(e);
        if (!options_.retainIntermediate) {
            std::lock_guard<std::mutex> lock(mutex_);
            for (const auto& n : wave)
                for (const auto& e : g.edgesInto(n))
                    if (--pendingReaders[e.from.node] == 0 && !targetSet.count(e.from.node)) {
                        NodeState& up = *states_.at(e.from.node);
                        up.valid = false;
                        up.outputs.clear();
                        up.origins.clear();
                    }
        }
    }
    if (cancel) throw Cancelled();
    std::lock_guard<std::mutex> lock(mutex_);
    enforceCap(targetSet);
}

void Evaluator::enforceCap(const std::set<std::string>& targets) {
    if (options_.cacheBytes == 0) return;
    if (cachedBytesLocked() <= options_.cacheBytes) return;
    // Least recently used first; never what this evaluation was asked for.
    std::vector<std::pair<std::uint64_t, std::string>> order;
    for (const auto& [name, st] : states_)
        if (st->valid && !targets.count(name)) order.emplace_back(st->lastUsed, name);
    std::sort(order.begin(), order.end());
    for (const auto& [age, name] : order) {
        if (cachedBytesLocked() <= options_.cacheBytes) break;
        NodeState& st = *states_.at(name);
        st.valid = false;
        st.outputs.clear();
        st.origins.clear();
    }
}

void Evaluator::process(const Graph& g, const Node& n, NodeState& st, const std::atomic<bool>& cancel) {
    const PortList& ports = g.ports(n);
    Inputs inputs = gatherInputs(g, n, ports, states_, mutex_);
    const std::uint64_t key = valueKey(n, ports, inputs, options_);
    const bool shareable = options_.sharedSources && readsNoImage(ports, inputs);

    NodeProfile profile;
    if (cacheHolds(st, inputs, key, profile.reason)) {
        auto [outputs, changed] = reassemble(st, inputs);
        profile.status = changed ? NodeProfile::Status::Reassembled : NodeProfile::Status::Cached;
        std::lock_guard<std::mutex> lock(mutex_);
        st.outputs = std::move(outputs);
        st.lastUsed = clock_;
    } else if (shareable && adoptShared(key, st)) {
        profile.status = NodeProfile::Status::Cached;
        profile.reason = "shared: another evaluator holds its result";
    } else {
        std::string why = std::move(profile.reason);
        profile = execute(g, n, st, std::move(inputs), key, cancel);
        profile.reason = std::move(why);
        if (shareable) publishShared(key, st);
    }
    profile.node = n.name;
    profile.type = n.type;

    std::lock_guard<std::mutex> lock(mutex_);
    profile_.push_back(std::move(profile));
    if (progress_) {
        std::lock_guard<std::mutex> plock(progress_->mutex);
        ++progress_->done;
        if (options_.onProgress)
            options_.onProgress(double(progress_->done) / double(std::max<std::size_t>(1, progress_->total)), n.name);
    }
}

bool Evaluator::adoptShared(std::uint64_t key, NodeState& st) {
    std::optional<SourceResult> found = options_.sharedSources->impl_->find(key);
    if (!found) return false;
    std::lock_guard<std::mutex> lock(mutex_);
    st.outputs = std::move(found->outputs);
    st.origins = std::move(found->origins);
    st.reads.clear();  // a source reads no image
    st.files = std::move(found->files);
    st.inputs = std::move(found->inputs);
    st.valueKey = key;
    st.valid = true;
    st.lastUsed = clock_;
    return true;
}

void Evaluator::publishShared(std::uint64_t key, const NodeState& st) {
    SourceResult r;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        r = {st.outputs, st.origins, st.files, st.inputs};
    }
    options_.sharedSources->impl_->store(key, r);
}

// Runs the node (its cached result no longer holds) and records the result.
NodeProfile Evaluator::execute(const Graph& g, const Node& n, NodeState& st, Inputs inputs, std::uint64_t key,
                               const std::atomic<bool>& cancel) {
    if (!st.filter || st.filterType != n.type) {
        st.filter = g.registry().createFilter(n.type);
        st.filterType = n.type;
    }
    NodeCall call;
    call.filter = st.filter.get();
    call.ports = &g.ports(n);
    call.name = n.name;
    call.type = n.type;
    call.inputs = std::move(inputs);
    call.inputBase = options_.inputBase;
    call.outputDir = options_.outputDir;
    call.registry = &g.registry();
    call.cancel = &cancel;
    call.upstreamInputs = [this, &g, &n] { return upstreamInputsOf(g, n.name, states_, mutex_); };
    call.onWarning = [&](const std::string& m) {
        if (!options_.onWarning) return;
        Diagnostic d;
        d.severity = Diagnostic::Severity::Warning;
        d.where = nodeLabel(n.name, n.type);
        d.message = m;
        d.node = n.name;
        options_.onWarning(d);
    };
    call.onProgress = [&](double f) {
        if (!options_.onProgress || !progress_) return;
        std::lock_guard<std::mutex> lock(progress_->mutex);
        options_.onProgress((double(progress_->done) + f) / double(std::max<std::size_t>(1, progress_->total)),
                            n.name);
    };
    // The previous entry is dropped first: its planes go back to the pool
    // for this execution, except those kept for comparison.
    std::map<std::string, Value> previous;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        previous = std::move(st.outputs);
        st.valid = false;
        st.outputs.clear();
    }
    beginSequenceOf(n, st);
    NodeResult r = runNode(call);
    keepUnchangedOutputs(r, previous);
    NodeProfile profile;
    profile.status = NodeProfile::Status::Ran;
    profile.seconds = r.seconds;
    profile.bytesAllocated = r.bytesAllocated;
    std::lock_guard<std::mutex> lock(mutex_);
    st.outputs = std::move(r.outputs);
    st.origins = std::move(r.origins);
    st.reads = std::move(r.reads);
    st.files = std::move(r.files);
    st.inputs = std::move(r.inputs);
    st.valueKey = key;
    st.valid = true;
    st.lastUsed = clock_;
    ++st.executions;
    st.seconds = r.seconds;
    return profile;
}

}  // namespace darkroom
