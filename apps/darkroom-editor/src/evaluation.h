#pragma once
// Live evaluation off the UI thread. Each request evaluates a copy of the
// graph on a worker thread with one long-lived Evaluator, so only nodes
// whose versions changed run again. A new request cancels the one running
// (Evaluator::cancel) and skips any still queued: only the latest counts.
// evaluator.h uses darkroom::Error without including its header.
#include <darkroom/error.h>
#include <darkroom/framework/evaluator.h>

#include <QObject>
#include <QThread>

#include <atomic>
#include <memory>

namespace editor {

struct EvalResult {
    darkroom::BufferPtr image;
    QString node;
    double seconds = 0;       // wall time of the whole request
    QString error;            // empty on success
    QStringList errorNodes;   // nodes the error names (shown red)
};

class Evaluation : public QObject {
    Q_OBJECT
public:
    explicit Evaluation(QObject* parent = nullptr);
    ~Evaluation() override;

    void request(const darkroom::Graph& graph, const QString& node, const QString& port, const QString& inputBase);
    bool busy() const { return pending_ > 0; }
    // Executions of a node so far (the evaluator's count; thread-safe).
    std::uint64_t executions(const QString& node) const;

signals:
    void started();
    void finished(const editor::EvalResult& result);

private:
    QThread thread_;
    QObject* worker_;  // lives on thread_; runs the queued jobs
    std::shared_ptr<darkroom::Evaluator> evaluator_;
    std::atomic<std::uint64_t> generation_{0};
    std::atomic<int> pending_{0};
};

}  // namespace editor

Q_DECLARE_METATYPE(editor::EvalResult)
