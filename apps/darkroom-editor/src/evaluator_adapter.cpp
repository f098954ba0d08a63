#include "evaluator_adapter.h"

#include "channel_port.h"

#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <set>

namespace editor {

std::vector<std::string> upstreamOf(const darkroom::Graph& graph, const std::string& node) {
    const std::set<std::string> needed = graph.upstreamOf({node});
    std::vector<std::string> order;
    try {
        for (const auto& n : graph.topologicalOrder())
            if (needed.count(n)) order.push_back(n);
    } catch (const std::exception&) {
        order.assign(needed.begin(), needed.end());  // a cycle: validation will report it
    }
    return order;
}

std::map<std::string, std::string> waitingForInput(const darkroom::Graph& graph, const std::string& node) {
    std::map<std::string, std::string> out;
    for (const auto& name : upstreamOf(graph, node)) {
        const darkroom::Node* n = graph.node(name);
        if (!n || n->placeholder) continue;
        for (const auto& in : graph.ports(*n).inputs)
            if (in.isImage() && !in.optional && graph.edgesInto(name, in.name).empty()) {
                out[name] = in.name;
                break;
            }
    }
    return out;
}

EvaluatorAdapter::EvaluatorAdapter() : evaluator_(std::make_shared<darkroom::Evaluator>()) {}

EvaluatorAdapter::EvaluatorAdapter(int threads, std::size_t cacheBytes) {
    darkroom::EvaluatorOptions o;
    o.threads = threads;
    o.cacheBytes = cacheBytes;
    evaluator_ = std::make_shared<darkroom::Evaluator>(o);
}
EvaluatorAdapter::~EvaluatorAdapter() = default;

void EvaluatorAdapter::setInputBase(const std::string& folder) {
    darkroom::EvaluatorOptions o = evaluator_->options();
    if (o.inputBase == folder) return;
    o.inputBase = folder;
    evaluator_->setOptions(o);  // clears the cache: relative paths now mean other files
}

void EvaluatorAdapter::shareSources(std::shared_ptr<darkroom::SharedSources> shared) {
    darkroom::EvaluatorOptions o = evaluator_->options();
    o.sharedSources = std::move(shared);
    evaluator_->setOptions(o);
}

void EvaluatorAdapter::cancel() {
    std::lock_guard<std::mutex> lock(mutex_);
    if (running_) *running_ = true;
}

std::uint64_t EvaluatorAdapter::executions(const std::string& node) const { return evaluator_->executions(node); }

double EvaluatorAdapter::lastSeconds(const std::string& node) const { return evaluator_->lastSeconds(node); }

darkroom::BufferPtr EvaluatorAdapter::evaluate(const darkroom::Graph& graph, const std::string& node,
                                               const std::string& port, const std::function<bool()>& stale,
                                               FrameProfile* profile) {
    if (stale && stale()) throw darkroom::Cancelled();
    const std::vector<std::string> nodes = upstreamOf(graph, node);
    auto flag = std::make_shared<std::atomic<bool>>(false);
    {
        std::lock_guard<std::mutex> lock(mutex_);
        running_ = flag;
    }
    struct Done {
        EvaluatorAdapter* self;
        ~Done() {
            std::lock_guard<std::mutex> lock(self->mutex_);
            self->running_.reset();
        }
    } done{this};

    darkroom::EvaluatorOptions o = evaluator_->options();
    o.onProgress = [stale, flag](double, const std::string&) {
        if (stale && stale()) *flag = true;
    };
    evaluator_->setOptions(o);
    const auto t0 = std::chrono::steady_clock::now();
    darkroom::BufferPtr image = evaluator_->evaluateImage(graph, node, port, flag.get());
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

    if (profile) {
        profile->nodes.clear();
        profile->seconds = wall;
        std::map<std::string, darkroom::NodeProfile> byNode;
        for (auto& p : evaluator_->lastProfile()) byNode[p.node] = p;
        for (const auto& n : nodes) {
            const auto it = byNode.find(n);
            const bool ran = it != byNode.end() && it->second.status == darkroom::NodeProfile::Status::Ran;
            const bool reassembled =
                it != byNode.end() && it->second.status == darkroom::NodeProfile::Status::Reassembled;
            profile->nodes.push_back({n, ran, reassembled, evaluator_->lastSeconds(n)});
        }
    }
    return image;
}

std::map<std::string, std::vector<std::string>> EvaluatorAdapter::inputChannels(const darkroom::Graph& graph,
                                                                               const std::vector<std::string>& nodes) {
    std::set<std::string> finished;
    for (const auto& p : evaluator_->lastProfile()) finished.insert(p.node);
    std::map<std::string, std::vector<std::string>> out;
    for (const auto& name : nodes) {
        const darkroom::Node* n = graph.node(name);
        if (!n || n->placeholder) continue;
        const auto& ports = graph.ports(*n);
        if (std::none_of(ports.inputs.begin(), ports.inputs.end(), isChannelPort)) continue;
        std::vector<std::string> channels;
        for (const auto& in : ports.inputs) {
            if (!in.isImage()) continue;
            for (const auto& e : graph.edgesInto(name, in.name)) {
                if (!finished.count(e.from.node)) continue;
                try {
                    const darkroom::BufferPtr b = evaluator_->evaluateImage(graph, e.from.node, e.from.port);
                    if (!b) continue;
                    for (const auto& c : b->channels())
                        if (std::find(channels.begin(), channels.end(), c.name) == channels.end())
                            channels.push_back(c.name);
                } catch (const std::exception&) {
                    // Not an image after all, or evicted and failing now: no list.
                }
            }
        }
        if (!channels.empty()) out[name] = std::move(channels);
    }
    return out;
}

double EvaluatorAdapter::predictSeconds(const darkroom::Graph& graph, const std::string& node) const {
    double total = 0;
    for (const auto& n : evaluator_->wouldRun(graph, {node})) {
        if (evaluator_->executions(n) == 0) return -1.0;
        total += evaluator_->lastSeconds(n);
    }
    return total;
}

}  // namespace editor
