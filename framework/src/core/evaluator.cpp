#include "host_context.h"

#include <darkroom/error.h>
#include <darkroom/framework/evaluator.h>

#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <set>

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

struct Evaluator::NodeState {
    std::uint64_t key = 0;
    bool valid = false;
    std::map<std::string, Value> outputs;
    std::unique_ptr<Filter> filter;
    std::string filterType;
    std::uint64_t executions = 0;
    double seconds = 0;
};

struct Evaluator::Progress {
    std::mutex mutex;
    std::size_t total = 0;
    std::size_t done = 0;
};

namespace {

std::uint64_t mix(std::uint64_t h, std::uint64_t v) {
    // splitmix64 finaliser over the running hash: cheap and well distributed.
    std::uint64_t z = h ^ (v + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2));
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

std::uint64_t hashString(const std::string& s) { return std::hash<std::string>{}(s); }

// Filters of a type that declares itself Unsafe share one lock.
std::mutex& typeLock(const std::string& type) {
    static std::mutex guard;
    static std::map<std::string, std::unique_ptr<std::mutex>> locks;
    std::lock_guard<std::mutex> g(guard);
    auto& m = locks[type];
    if (!m) m = std::make_unique<std::mutex>();
    return *m;
}

}  // namespace

Evaluator::Evaluator(EvaluatorOptions options) : options_(std::move(options)) {}
Evaluator::~Evaluator() = default;

void Evaluator::setOptions(EvaluatorOptions options) {
    std::lock_guard<std::mutex> lock(mutex_);
    // Paths change what readers and writers do: cached results are stale.
    if (options.inputBase != options_.inputBase || options.outputDir != options_.outputDir) states_.clear();
    options_ = std::move(options);
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

void Evaluator::clearCache() {
    std::lock_guard<std::mutex> lock(mutex_);
    states_.clear();
}

std::uint64_t Evaluator::cacheKey(const Graph& g, const std::string& name,
                                  std::map<std::string, std::uint64_t>& memo) const {
    if (auto it = memo.find(name); it != memo.end()) return it->second;
    const Node* n = g.node(name);
    std::uint64_t h = mix(hashString(n->type), n->version);
    for (const auto& e : g.edgesInto(name)) {
        h = mix(h, cacheKey(g, e.from.node, memo));
        h = mix(h, hashString(e.from.port));
        h = mix(h, hashString(e.to.port));
    }
    memo[name] = h;
    return h;
}

Value Evaluator::evaluate(const Graph& graph, const std::string& node, const std::string& port) {
    const Node* n = graph.node(node);
    if (!n) throw Error("no node named '" + node + "'");
    if (!n->placeholder && !graph.ports(*n).output(port))
        throw Error("node '" + node + "' (" + n->type + ") has no output '" + port + "'");
    ensure(graph, {node});
    std::lock_guard<std::mutex> lock(mutex_);
    return states_.at(node)->outputs.at(port);
}

BufferPtr Evaluator::evaluateImage(const Graph& graph, const std::string& node, const std::string& port) {
    return evaluate(graph, node, port).asImage();
}

void Evaluator::run(const Graph& graph, std::vector<std::string> nodes) {
    if (nodes.empty()) nodes = graph.sinks();
    if (nodes.empty())
        throw Error("the pipeline has no output node (a node without outputs, such as ImageWriter)");
    for (const auto& n : nodes)
        if (!graph.node(n)) throw Error("no node named '" + n + "'");
    ensure(graph, nodes);
}

void Evaluator::ensure(const Graph& g, const std::vector<std::string>& targets) {
    cancelled_ = false;
    // The part of the graph the targets depend on.
    std::set<std::string> needed;
    std::function<void(const std::string&)> collect = [&](const std::string& n) {
        if (!needed.insert(n).second) return;
        for (const auto& e : g.edgesInto(n))
            if (g.node(e.from.node)) collect(e.from.node);
    };
    for (const auto& t : targets) collect(t);

    // Everything is checked before anything runs.
    Diagnostics problems;
    for (auto& d : g.validate())
        if (d.severity == Diagnostic::Severity::Error && (d.node.empty() || needed.count(d.node)))
            problems.push_back(std::move(d));
    if (!problems.empty()) throw GraphError(std::move(problems));

    // Depth levels: a node runs after everything it reads; nodes of one level
    // are independent and run concurrently.
    std::map<std::string, std::uint64_t> memo;
    std::map<std::string, int> level;
    std::function<int(const std::string&)> depth = [&](const std::string& n) -> int {
        if (auto it = level.find(n); it != level.end()) return it->second;
        int d = 0;
        for (const auto& e : g.edgesInto(n)) d = std::max(d, depth(e.from.node) + 1);
        return level[n] = d;
    };
    std::vector<std::vector<std::string>> waves;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        for (const auto& n : g.topologicalOrder()) {
            if (!needed.count(n)) continue;
            const std::uint64_t key = cacheKey(g, n, memo);
            auto& st = states_[n];
            if (!st) st = std::make_unique<NodeState>();
            if (st->valid && st->key == key) continue;
            st->valid = false;
            const int d = depth(n);
            if (int(waves.size()) <= d) waves.resize(d + 1);
            waves[d].push_back(n);
        }
    }
    Progress progress;
    for (const auto& w : waves) progress.total += w.size();
    progress_ = &progress;

    tbb::task_arena arena(options_.threads > 0 ? options_.threads : tbb::task_arena::automatic);
    for (const auto& wave : waves) {
        if (wave.empty()) continue;
        if (cancelled_) throw Cancelled();
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
                    execute(g, n, memo.at(n.name), *st);
                } catch (...) {
                    errors[i] = std::current_exception();
                }
            });
        });
        // Report the first failure in graph order, so messages do not depend
        // on scheduling.
        for (auto& e : errors)
            if (e) {
                progress_ = nullptr;
                std::rethrow_exception(e);
            }
    }
    progress_ = nullptr;
    if (cancelled_) throw Cancelled();
}

void Evaluator::execute(const Graph& g, const Node& n, std::uint64_t key, NodeState& st) {
    const PortList& ports = g.ports(n);
    HostContext::Setup setup;
    setup.nodeName = n.name;
    setup.ports = &ports;
    setup.inputBase = options_.inputBase;
    setup.outputDir = options_.outputDir;
    setup.registry = &g.registry();
    setup.cancelFlag = &cancelled_;
    setup.onWarning = [&](const std::string& m) {
        if (options_.onWarning) {
            Diagnostic d;
            d.severity = Diagnostic::Severity::Warning;
            d.where = "node '" + n.name + "'";
            d.message = m;
            d.node = n.name;
            options_.onWarning(d);
        }
    };
    setup.onProgress = [&](double f) {
        if (!options_.onProgress || !progress_) return;
        std::lock_guard<std::mutex> lock(progress_->mutex);
        options_.onProgress((double(progress_->done) + f) / double(std::max<std::size_t>(1, progress_->total)),
                            n.name);
    };

    for (const auto& in : ports.inputs) {
        const auto edges = g.edgesInto(n.name, in.name);
        std::vector<Value> values;
        for (const auto& e : edges) {
            std::lock_guard<std::mutex> lock(mutex_);
            const NodeState& up = *states_.at(e.from.node);
            auto it = up.outputs.find(e.from.port);
            if (it == up.outputs.end())
                throw Error("node '" + n.name + "': upstream " + e.from.str() + " produced nothing");
            Value v = it->second;
            if (in.type == PortType::Float && std::holds_alternative<std::int64_t>(v.storage()))
                v = Value(v.asFloat());
            values.push_back(std::move(v));
        }
        if (values.empty() && in.type != PortType::Image) {
            if (const Value* p = n.parameter(in.name)) values.push_back(*p);
        }
        if (in.type == PortType::Image) {
            for (const auto& v : values) {
                const BufferPtr& b = v.asImage();
                if (!b) throw Error("node '" + n.name + "': input '" + in.name + "' received no image");
                for (const auto& c : in.channels)
                    if (!b->hasChannel(c)) {
                        std::string have;
                        for (const auto& x : b->channelNames()) have += (have.empty() ? "" : ", ") + x;
                        throw Error("node '" + n.name + "' (" + n.type + "): input '" + in.name +
                                    "' needs channel '" + c + "', but the image has " +
                                    (have.empty() ? std::string("no channels") : have));
                    }
            }
        }
        if (!values.empty()) setup.inputs[in.name] = std::move(values);
    }

    if (!st.filter || st.filterType != n.type) {
        st.filter = g.registry().createFilter(n.type);
        st.filterType = n.type;
    }
    HostContext ctx(std::move(setup));
    const auto t0 = std::chrono::steady_clock::now();
    try {
        std::unique_lock<std::mutex> typeGuard;
        if (st.filter->threadSafety() == ThreadSafety::Unsafe)
            typeGuard = std::unique_lock<std::mutex>(typeLock(n.type));
        st.filter->execute(ctx);
    } catch (const Cancelled&) {
        throw;
    } catch (const std::exception& e) {
        // One error boundary for every call into a plugin.
        throw Error("node '" + n.name + "' (" + n.type + "): " + e.what());
    } catch (...) {
        throw Error("node '" + n.name + "' (" + n.type + "): failed with an unknown exception");
    }
    if (cancelled_) throw Cancelled();
    for (const auto& out : ports.outputs)
        if (!ctx.outputs().count(out.name))
            throw Error("node '" + n.name + "' (" + n.type + ") did not produce its output '" + out.name + "'");

    std::lock_guard<std::mutex> lock(mutex_);
    st.outputs = std::move(ctx.outputs());
    st.key = key;
    st.valid = true;
    ++st.executions;
    st.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (progress_) {
        std::lock_guard<std::mutex> plock(progress_->mutex);
        ++progress_->done;
        if (options_.onProgress)
            options_.onProgress(double(progress_->done) / double(std::max<std::size_t>(1, progress_->total)), n.name);
    }
}

}  // namespace darkroom
