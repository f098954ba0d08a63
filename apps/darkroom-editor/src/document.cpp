#include "document.h"

#include "layout.h"

#include <darkroom/error.h>
#include <darkroom/core/pipeline.h>

#include <QFileInfo>
#include <QUndoCommand>

namespace editor {
namespace {

class GraphCommand : public QUndoCommand {
public:
    GraphCommand(Document* doc, const QString& text, darkroom::Graph before, darkroom::Graph after,
                 const QString& mergeKey)
        : QUndoCommand(text), doc_(doc), before_(std::move(before)), after_(std::move(after)),
          mergeKey_(mergeKey) {}
    void undo() override { doc_->replaceGraph(before_); }
    void redo() override { doc_->replaceGraph(after_); }
    int id() const override { return mergeKey_.isEmpty() ? -1 : 1; }
    bool mergeWith(const QUndoCommand* other) override {
        auto* o = static_cast<const GraphCommand*>(other);
        if (o->mergeKey_ != mergeKey_) return false;
        after_ = o->after_;
        return true;
    }

private:
    Document* doc_;
    darkroom::Graph before_, after_;
    QString mergeKey_;
};

}  // namespace

Document::Document(const darkroom::Registry& registry, QObject* parent)
    : QObject(parent), registry_(&registry), graph_(registry) {}

QString Document::folder() const {
    return path_.isEmpty() ? QString() : QFileInfo(path_).absolutePath();
}

QString Document::edit(const QString& text, const std::function<void(darkroom::Graph&)>& fn,
                       const QString& mergeKey) {
    darkroom::Graph after = graph_;
    try {
        fn(after);
    } catch (const std::exception& e) {
        return QString::fromStdString(e.what());
    }
    undo_.push(new GraphCommand(this, text, graph_, std::move(after), mergeKey));
    return {};
}

void Document::replaceGraph(darkroom::Graph g) {
    graph_ = std::move(g);
    emit changed();
}

void Document::clear() {
    undo_.clear();
    graph_ = darkroom::Graph(*registry_);
    path_.clear();
    emit pathChanged();
    emit changed();
}

bool Document::restore(const QString& text, const QString& originalPath, const QString& source,
                       QStringList& messages) {
    darkroom::Diagnostics d;
    darkroom::Graph g = darkroom::parsePipeline(text.toStdString(), source.toStdString(), *registry_, d);
    for (const auto& x : d) messages << QString::fromStdString(x.str());
    if (darkroom::hasErrors(d) && g.nodes().empty()) return false;
    undo_.clear();
    graph_ = std::move(g);
    path_ = originalPath.isEmpty() ? QString() : QFileInfo(originalPath).absoluteFilePath();
    undo_.resetClean();  // recovered edits are unsaved
    emit pathChanged();
    emit changed();
    return true;
}

bool Document::load(const QString& path, QStringList& messages) {
    darkroom::Diagnostics d;
    darkroom::Graph g = darkroom::loadPipeline(path.toStdString(), *registry_, d);
    for (const auto& x : d) messages << QString::fromStdString(x.str());
    if (darkroom::hasErrors(d) && g.nodes().empty()) return false;
    autoLayout(g);
    undo_.clear();
    graph_ = std::move(g);
    path_ = QFileInfo(path).absoluteFilePath();
    undo_.setClean();
    emit pathChanged();
    emit changed();
    return true;
}

bool Document::save(const QString& path, QString* error) {
    try {
        darkroom::savePipeline(graph_, path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    path_ = QFileInfo(path).absoluteFilePath();
    undo_.setClean();
    emit pathChanged();
    return true;
}

QString Document::uniqueName(const QString& base) const {
    QString b = base.toLower();
    if (!graph_.node(b.toStdString())) return b;
    for (int i = 2;; ++i) {
        const QString n = b + QString::number(i);
        if (!graph_.node(n.toStdString())) return n;
    }
}

}  // namespace editor
