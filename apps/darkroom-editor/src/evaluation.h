#pragma once
// Live evaluation that follows the hand. Every request (an edit, another
// node shown) is evaluated off the UI thread on a copy of the graph:
//  - when the nodes that must run again took longer than the preview budget
//    last time (or a value is being dragged), a reduced-resolution preview
//    runs first (preview_graph.h), at the largest size predicted to fit the
//    budget, corrected by what previews actually took;
//  - when the hand stops (the drag ends, or no new value for a moment) the
//    latest request settles at full resolution;
//  - a newer request cancels a full-resolution run in progress when that run
//    is slow (predicted over the budget, or of unknown cost); quick runs and
//    previews are coalesced instead (the newest waiting one runs next);
//  - the preview size stays fixed during a drag (a new size would resample
//    the sources again), coarser only if a preview overran the budget, or
//    if previews reached the screen late: an edit waits on average half a
//    preview for the worker, then its own preview, then the window's frame,
//    so the compute budget alone does not bound input-to-pixels. Frames
//    later than 1.5 budgets after their edit (median of 4) make the rest of
//    the drag one level coarser. The next drag starts no finer than the
//    last one ended (one level finer if its frames came in under half
//    that): the prediction is noisy on a loaded machine, and every new size
//    resamples the sources, so trying finer sizes costs frames;
//  - after a slow full-resolution frame the preview evaluator is warmed in
//    the background (sources downsampled), once that frame is on screen, so
//    the first drag step does not wait for the sources to be downsampled;
//  - when the hand stops, a preview still waiting is dropped: the full
//    frame of the same edit follows, and needs both cores.
// Two workers, each with its own evaluator and cache: previews never evict
// the full-resolution results, and a preview never waits behind a full run.
// The sources' results are shared between the two (SharedSources): each
// database is read once, by whichever evaluator needs it first.
#include "eval_worker.h"

#include <QElapsedTimer>
#include <QObject>
#include <QTimer>

#include <atomic>
#include <map>
#include <vector>

namespace editor {

class Evaluation : public QObject {
    Q_OBJECT
public:
    explicit Evaluation(QObject* parent = nullptr);
    ~Evaluation() override;

    void request(const darkroom::Graph& graph, const QString& node, const QString& port, const QString& inputBase);
    // True while a value is being dragged: requests preview, settling waits
    // for the end of the drag (or a pause of the hand).
    void setInteracting(bool on);
    bool interacting() const { return interacting_; }
    // Work waits, runs or is about to settle.
    bool busy() const;

    // Target time of one preview frame (default 50 ms); 0 disables previews.
    void setPreviewBudget(double seconds) { budget_ = seconds; }
    double previewBudget() const { return budget_; }
    // How long after the last value the frame settles at full resolution.
    void setSettleDelay(int ms) { settleDelayMs_ = ms; }

    // The preview level chosen for the current or last drag (0: none).
    int previewLevel() const { return level_; }
    // Executions of a node by the full-resolution and the preview evaluator.
    std::uint64_t executions(const QString& node) const;
    std::uint64_t previewExecutions(const QString& node) const;
    std::uint64_t generation() const { return generation_; }
    // The frame of `generation` at preview `level` reached the screen.
    void framePresented(std::uint64_t generation, int level);

signals:
    void started();
    void finished(const editor::EvalResult& result);  // previews and settled frames

private:
    void settle();
    void onDone(const EvalResult& r);
    int chooseLevel(double predicted) const;
    void warmPreview();
    bool isSource(const darkroom::Graph& g, const QString& node) const;
    void endDrag();

    EvalWorker* full_;
    EvalWorker* preview_;
    QTimer settleTimer_;
    EvalJob latest_;
    bool latestSettled_ = true;  // the latest request went (or goes) to full resolution
    bool interacting_ = false;
    std::atomic<double> budget_{0.05};  // also read by the full worker's thread
    int settleDelayMs_ = 150;
    double previewCorrection_ = 1.0;  // measured preview time / predicted, smoothed
    int level_ = 0;                   // preview level of the current drag (0: none chosen)
    int floorLevel_ = 0;              // the coarsest level a drag starts at: where the last drag ended
    QElapsedTimer clock_;
    std::map<std::uint64_t, double> requestedAt_;  // ms on clock_, previews not yet on screen
    std::vector<double> latencies_;                // ms from edit to screen, frames at level_ not yet judged
    std::vector<double> dragLatencies_;            // the whole drag's
    std::atomic<std::uint64_t> generation_{0};
    std::uint64_t shownGeneration_ = 0;
    // A warm-up of the preview evaluator due once the full frame of this
    // generation is on screen (0: none): started earlier it would take the
    // CPU from the view's upload of that frame. `warmSeconds_`: its cost.
    std::uint64_t warmDue_ = 0;
    double warmSeconds_ = 0;
    int shownLevel_ = 0;
};

}  // namespace editor
