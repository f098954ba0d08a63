#include "evaluation.h"

#include <darkroom/core/shared_sources.h>

#include <algorithm>
#include <cmath>
#include <utility>

namespace editor {
namespace {

constexpr int kMaxLevel = 5;          // 1/32 of each side: 1024 px becomes 32
constexpr double kBudgetShare = 0.8;  // aim below the budget: timings vary
constexpr double kLatencyShare = 1.5; // a preview's frame on screen within 1.5 budgets of its edit
constexpr std::size_t kLatencyFrames = 4;
constexpr int kWarmFallbackMs = 500;  // the warm-up starts by then even if no frame was presented

double median(std::vector<double> v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return v[v.size() / 2];
}

}  // namespace

Evaluation::Evaluation(QObject* parent) : QObject(parent) {
    // A newer edit cancels a full-resolution run that is slow (over the
    // budget, or of unknown cost); a quick one finishes and is shown, so
    // cheap pipelines follow a drag frame by frame without previews.
    auto slow = [this](const EvalJob& j) { return j.predicted < 0 || j.predicted > budget_; };
    full_ = new EvalWorker(slow, [this, slow](const EvalJob& j) { return j.generation != generation_ && slow(j); },
                           this);
    // A preview is never cancelled for a newer value (see the header); it
    // only stops when the editor closes.
    preview_ = new EvalWorker([](const EvalJob&) { return false; }, [](const EvalJob&) { return false; }, this);
    // One read of the sources for both: the preview evaluator takes the
    // full one's databases (and the other way round) instead of reading them
    // again, so its warm-up after the first frame only downsamples.
    const auto shared = std::make_shared<darkroom::SharedSources>();
    full_->adapter().shareSources(shared);
    preview_->adapter().shareSources(shared);
    connect(full_, &EvalWorker::done, this, &Evaluation::onDone);
    connect(preview_, &EvalWorker::done, this, &Evaluation::onDone);
    settleTimer_.setSingleShot(true);
    connect(&settleTimer_, &QTimer::timeout, this, &Evaluation::settle);
    clock_.start();
}

Evaluation::~Evaluation() {
    ++generation_;  // everything running is stale now
    delete full_;
    delete preview_;
}

bool Evaluation::busy() const { return full_->busy() || preview_->busy() || settleTimer_.isActive(); }

std::uint64_t Evaluation::executions(const QString& node) const {
    return full_->adapter().executions(node.toStdString());
}

std::uint64_t Evaluation::previewExecutions(const QString& node) const {
    return preview_->adapter().executions(node.toStdString());
}

bool Evaluation::isSource(const darkroom::Graph& g, const QString& node) const {
    for (const auto& e : g.edgesInto(node.toStdString())) {
        const darkroom::Node* up = g.node(e.from.node);
        const darkroom::PortSpec* spec = up && !up->placeholder ? g.ports(*up).output(e.from.port) : nullptr;
        if (spec && spec->isImage()) return false;
    }
    return true;
}

int Evaluation::chooseLevel(double predicted) const {
    // Work downstream of the sources scales with the pixel count: each level
    // quarters it. The correction carries what previews really took.
    const double full = std::max(predicted, 1e-6) * previewCorrection_;
    for (int k = 1; k < kMaxLevel; ++k)
        if (full / std::pow(4.0, k) <= kBudgetShare * budget_) return std::max(k, floorLevel_);
    return kMaxLevel;
}

void Evaluation::request(const darkroom::Graph& graph, const QString& node, const QString& port,
                         const QString& inputBase) {
    EvalJob job;
    job.graph = std::make_shared<const darkroom::Graph>(graph);
    job.node = node;
    job.port = port;
    job.inputBase = inputBase;
    job.generation = ++generation_;  // makes a full run in progress stale
    job.predicted = full_->adapter().predictSeconds(graph, node.toStdString());
    latest_ = job;
    emit started();

    // Nothing known about the cost (a pipeline just opened): the full frame
    // directly, since a preview would read the same sources first.
    const bool slow = job.predicted < 0 ? interacting_ : job.predicted > budget_;
    if (budget_ <= 0 || !slow || isSource(graph, node)) {
        settleTimer_.stop();
        latestSettled_ = true;
        full_->submit(job);
        return;
    }
    // One size for the whole drag; outside a drag each edit chooses afresh.
    if (!interacting_ || level_ == 0) level_ = chooseLevel(job.predicted < 0 ? 1.0 : job.predicted);
    job.level = level_;
    latestSettled_ = false;
    requestedAt_.erase(requestedAt_.begin(), requestedAt_.lower_bound(job.generation > 64 ? job.generation - 64 : 0));
    requestedAt_[job.generation] = clock_.nsecsElapsed() / 1e6;
    preview_->submit(job);
    // A pause of the hand also settles, even while the button is held.
    settleTimer_.start(interacting_ ? 2 * settleDelayMs_ : settleDelayMs_);
}

void Evaluation::setInteracting(bool on) {
    if (on == interacting_) return;
    interacting_ = on;
    latencies_.clear();
    if (!on) {
        endDrag();
        settleTimer_.stop();
        settle();
    }
}

void Evaluation::framePresented(std::uint64_t generation, int level) {
    if (level == 0 && warmDue_ != 0 && generation >= warmDue_) warmPreview();
    const auto it = requestedAt_.find(generation);
    if (it == requestedAt_.end()) return;
    const double ms = clock_.nsecsElapsed() / 1e6 - it->second;
    requestedAt_.erase(requestedAt_.begin(), std::next(it));
    if (level == 0 || !interacting_ || level != level_ || budget_ <= 0) return;
    dragLatencies_.push_back(ms);
    latencies_.push_back(ms);
    if (latencies_.size() < kLatencyFrames) return;
    const double late = median(latencies_);
    latencies_.clear();
    if (late > kLatencyShare * budget_ * 1000.0 && level_ < kMaxLevel) ++level_;
}

void Evaluation::endDrag() {
    // Previews well in time: the next drag may try one size finer.
    if (dragLatencies_.empty()) return;
    const bool quick = median(dragLatencies_) < 0.5 * kLatencyShare * budget_ * 1000.0;
    floorLevel_ = std::max(0, quick ? level_ - 1 : level_);
    dragLatencies_.clear();
}

void Evaluation::settle() {
    if (latestSettled_ || !latest_.graph) return;
    latestSettled_ = true;
    preview_->dropPending();
    EvalJob job = latest_;
    job.level = 0;
    full_->submit(job);
}

void Evaluation::warmPreview() {
    const std::uint64_t due = std::exchange(warmDue_, 0);
    if (due == 0 || due != latest_.generation || !latestSettled_) return;  // an edit came first
    EvalJob job = latest_;
    // The size the next drag starts with, from what this frame cost.
    level_ = chooseLevel(std::max(warmSeconds_, 1e-3));
    job.level = level_;
    job.show = false;
    preview_->submit(job);
}

void Evaluation::onDone(const EvalResult& r) {
    if (!r.show) return;  // a warm-up: the cache is what it was for
    if (r.level > 0) {
        // Learn how far the prediction was off at this size, and coarsen a
        // drag whose previews overrun the budget clearly.
        const double predicted = r.predicted > 0 ? r.predicted / std::pow(4.0, r.level) : 0;
        if (predicted > 0 && r.error.isEmpty()) {
            const double ratio = std::clamp(r.profile.seconds / predicted, 0.25, 16.0);
            previewCorrection_ = std::clamp(0.5 * previewCorrection_ + 0.5 * ratio, 0.25, 16.0);
        }
        if (interacting_ && r.level == level_ && r.profile.seconds > 1.5 * budget_ && level_ < kMaxLevel) {
            ++level_;
            latencies_.clear();  // judged at the new size
        }
        // A preview that fails (or is older than what is shown) says
        // nothing the settled frame will not say better.
        if (!r.error.isEmpty()) {
            if (r.generation == latest_.generation) {
                settleTimer_.stop();
                settle();
            }
            return;
        }
        if (r.generation <= shownGeneration_) return;
    } else {
        // An error of an edit already replaced (a half-made change) is noise.
        if (!r.error.isEmpty() && r.generation != latest_.generation) return;
        // A full frame replaces a preview of the same edit, never a newer one.
        if (r.generation < shownGeneration_ || (r.generation == shownGeneration_ && shownLevel_ == 0)) return;
    }
    shownGeneration_ = r.generation;
    shownLevel_ = r.level;
    emit finished(r);
    // Only where previews will be used: the frame was slower than the budget.
    if (r.level == 0 && r.error.isEmpty() && budget_ > 0 && r.profile.seconds > budget_ &&
        r.generation == latest_.generation) {
        warmDue_ = r.generation;
        warmSeconds_ = r.profile.seconds;
        // framePresented() starts it; this is for a view that never presents.
        QTimer::singleShot(kWarmFallbackMs, this, &Evaluation::warmPreview);
    }
}

}  // namespace editor
