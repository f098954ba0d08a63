#pragma once
// One evaluator on its own thread, fed with "the latest job": submitting
// while a job waits replaces it (only the newest counts), and the worker
// takes the newest job whenever it becomes free. Whether a newer job also
// cancels the one running is the owner's choice per running job: cancelling
// long work that is stale saves seconds, while cancelling short work before
// it lands would starve a continuous drag of frames.
#include "evaluator_adapter.h"

#include <darkroom/core/graph.h>

#include <QObject>
#include <QString>
#include <QStringList>
#include <QThread>

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>

namespace editor {

struct EvalJob {
    std::shared_ptr<const darkroom::Graph> graph;
    QString node, port, inputBase;
    std::uint64_t generation = 0;
    int level = 0;            // 0 = full resolution; k = every source at 1/2^k
    double predicted = -1;    // full-resolution seconds predicted for the dirty nodes
    bool show = true;         // false: only fills the cache (its result is not shown)
};

struct EvalResult {
    darkroom::BufferPtr image;
    QString node;
    int level = 0;
    std::uint64_t generation = 0;
    FrameProfile profile;
    double predicted = -1;
    bool show = true;
    QString error;            // empty on success
    QStringList errorNodes;   // nodes the error names (shown red)
    // Full-resolution frames: the channels flowing into each evaluated node
    // that has a channel port (its drop-down).
    std::map<QString, QStringList> inputChannels;
};

class EvalWorker : public QObject {
    Q_OBJECT
public:
    // `stale` tells whether a job is out of date (asked on the worker
    // thread, also while it runs); `cancelOnSubmit` whether a newer job
    // cancels the running one (asked on the owner's thread).
    EvalWorker(std::function<bool(const EvalJob&)> cancelOnSubmit, std::function<bool(const EvalJob&)> stale,
               QObject* parent = nullptr);
    ~EvalWorker() override;

    void submit(EvalJob job);
    // Forgets the job waiting (not the one running): a full frame of the
    // same edit is on its way, and on two cores the preview would only take
    // CPU from it.
    void dropPending();
    // A job waits, runs, or its result has not been delivered yet.
    bool busy() const;
    EvaluatorAdapter& adapter() { return adapter_; }
    const EvaluatorAdapter& adapter() const { return adapter_; }

signals:
    void done(const editor::EvalResult& result);  // on the owner's thread

private:
    void runPending();  // on the worker thread
    std::optional<EvalResult> evaluate(const EvalJob& job);  // nullopt: cancelled

    const std::function<bool(const EvalJob&)> cancelOnSubmit_;
    const std::function<bool(const EvalJob&)> stale_;
    EvaluatorAdapter adapter_;
    QThread thread_;
    QObject* context_;  // lives on thread_
    mutable std::mutex mutex_;
    std::optional<EvalJob> pending_;
    EvalJob running_job_;  // what runs now (valid while running_)
    bool posted_ = false;
    bool running_ = false;
    int undelivered_ = 0;
    std::atomic<bool> stopping_{false};
};

}  // namespace editor

Q_DECLARE_METATYPE(editor::EvalResult)
