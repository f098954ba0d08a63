#include "eval_worker.h"

#include "preview_graph.h"

#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>

namespace editor {

EvalWorker::EvalWorker(std::function<bool(const EvalJob&)> cancelOnSubmit, std::function<bool(const EvalJob&)> stale,
                       QObject* parent)
    : QObject(parent), cancelOnSubmit_(std::move(cancelOnSubmit)), stale_(std::move(stale)),
      context_(new QObject) {
    qRegisterMetaType<editor::EvalResult>();
    context_->moveToThread(&thread_);
    connect(&thread_, &QThread::finished, context_, &QObject::deleteLater);
    thread_.start();
}

EvalWorker::~EvalWorker() {
    stopping_ = true;
    adapter_.cancel();
    thread_.quit();
    thread_.wait();
}

bool EvalWorker::busy() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return posted_ || running_ || undelivered_ > 0;
}

void EvalWorker::submit(EvalJob job) {
    bool cancel = false;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        pending_ = std::move(job);
        cancel = running_ && cancelOnSubmit_(running_job_);
        if (!posted_) {
            posted_ = true;
            QMetaObject::invokeMethod(context_, [this] { runPending(); }, Qt::QueuedConnection);
        }
    }
    // A cancel that lands on the next job instead is caught in runPending.
    if (cancel) adapter_.cancel();
}

void EvalWorker::dropPending() {
    std::lock_guard<std::mutex> lock(mutex_);
    pending_.reset();  // a runPending already posted finds nothing
}

void EvalWorker::runPending() {
    EvalJob job;
    {
        std::lock_guard<std::mutex> lock(mutex_);
        posted_ = false;
        if (!pending_ || stopping_) return;
        job = std::move(*pending_);
        pending_.reset();
        running_ = true;
        running_job_ = job;
    }
    const std::optional<EvalResult> result = evaluate(job);
    const bool deliver = !stopping_ && result;  // a cancelled job has nothing to say
    std::lock_guard<std::mutex> lock(mutex_);
    running_ = false;
    if (deliver) {
        ++undelivered_;
        // Queued to the owner's thread; dropped by Qt if this object is gone.
        QMetaObject::invokeMethod(this, [this, r = *result] {
            {
                std::lock_guard<std::mutex> l(mutex_);
                --undelivered_;
            }
            emit done(r);
        }, Qt::QueuedConnection);
    }
}

std::optional<EvalResult> EvalWorker::evaluate(const EvalJob& job) {
    EvalResult r;
    r.node = job.node;
    r.level = job.level;
    r.generation = job.generation;
    r.predicted = job.predicted;
    r.show = job.show;
    auto stale = [this, &job] { return stopping_ || stale_(job); };
    for (;;) {
        bool invalid = false;
        try {
            adapter_.setInputBase(job.inputBase.toStdString());
            if (job.level > 0) {
                const darkroom::Graph preview = makePreviewGraph(*job.graph, job.level);
                r.image = adapter_.evaluate(preview, job.node.toStdString(), job.port.toStdString(), stale, &r.profile);
            } else {
                r.image = adapter_.evaluate(*job.graph, job.node.toStdString(), job.port.toStdString(), stale,
                                            &r.profile);
            }
        } catch (const darkroom::Cancelled&) {
            // A cancel meant for the job before this one can land here: a job
            // that is still current runs again.
            if (!stale()) continue;
            return std::nullopt;
        } catch (const darkroom::GraphError& e) {
            invalid = true;  // nothing ran: the last profile is another graph's
            r.error = QString::fromStdString(e.what());
            for (const auto& d : e.diagnostics())
                if (!d.node.empty()) r.errorNodes << QString::fromStdString(d.node);
        } catch (const darkroom::Error& e) {
            r.error = QString::fromStdString(e.what());
            if (!e.node().empty()) r.errorNodes << QString::fromStdString(e.node());  // the evaluator says which
            if (r.error.isEmpty()) r.error = QStringLiteral("evaluation failed");
        } catch (const std::exception& e) {
            r.error = QString::fromStdString(e.what());
            if (r.error.isEmpty()) r.error = QStringLiteral("evaluation failed");
        }
        if (job.level == 0 && job.show && !invalid) {
            for (auto& [node, channels] : adapter_.inputChannels(*job.graph, upstreamOf(*job.graph, job.node.toStdString())))
                for (const auto& c : channels) r.inputChannels[QString::fromStdString(node)] << QString::fromStdString(c);
        }
        return r;
    }
}

}  // namespace editor
