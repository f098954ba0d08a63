#include "evaluation.h"

#include <darkroom/error.h>

#include <QElapsedTimer>

namespace editor {

Evaluation::Evaluation(QObject* parent)
    : QObject(parent), worker_(new QObject), evaluator_(std::make_shared<darkroom::Evaluator>()) {
    qRegisterMetaType<editor::EvalResult>();
    worker_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, worker_, &QObject::deleteLater);
    thread_.start();
}

Evaluation::~Evaluation() {
    ++generation_;
    evaluator_->cancel();
    thread_.quit();
    thread_.wait();
}

std::uint64_t Evaluation::executions(const QString& node) const {
    return evaluator_->executions(node.toStdString());
}

void Evaluation::request(const darkroom::Graph& graph, const QString& node, const QString& port,
                         const QString& inputBase) {
    const std::uint64_t gen = ++generation_;
    evaluator_->cancel();  // the running job stops at its next check
    ++pending_;
    emit started();
    auto copy = std::make_shared<darkroom::Graph>(graph);
    auto evaluator = evaluator_;
    QMetaObject::invokeMethod(worker_, [=, this] {
        EvalResult r;
        r.node = node;
        bool cancelled = gen != generation_;  // a newer request is queued behind us
        if (!cancelled) {
            QElapsedTimer t;
            t.start();
            darkroom::EvaluatorOptions o = evaluator->options();
            o.inputBase = inputBase.toStdString();
            evaluator->setOptions(o);
            try {
                r.image = evaluator->evaluateImage(*copy, node.toStdString(), port.toStdString());
            } catch (const darkroom::Cancelled&) {
                cancelled = true;
            } catch (const darkroom::GraphError& e) {
                r.error = QString::fromStdString(e.what());
                for (const auto& d : e.diagnostics())
                    if (!d.node.empty()) r.errorNodes << QString::fromStdString(d.node);
            } catch (const std::exception& e) {
                r.error = QString::fromStdString(e.what());
                for (const auto& n : copy->nodes())
                    if (r.error.contains(QString::fromStdString("node '" + n.name + "'")))
                        r.errorNodes << QString::fromStdString(n.name);
            }
            r.seconds = t.elapsed() / 1000.0;
        }
        // Queued to the UI thread; dropped by Qt if this object is gone.
        QMetaObject::invokeMethod(this, [this, r, cancelled, gen] {
            --pending_;
            if (!cancelled && gen == generation_) emit finished(r);
        }, Qt::QueuedConnection);
    }, Qt::QueuedConnection);
}

}  // namespace editor
