// MainWindow: the explorer dock and its links. The explorer's items are the
// Cinema browser's entries: picking one in the explorer picks it in the
// browser (which drives the CinemaReader, hence the render view, and moves
// its sliders), and the browser's choice is highlighted in the explorer.
// The selection is saved in that CinemaReader node (`explore:`), as an
// undoable edit at the end of each gesture, and opening a pipeline that has
// it opens the database with the selection back.
#include "main_window.h"

#include "cinema_panel.h"
#include "document.h"
#include "evaluator_adapter.h"
#include "explorer_panel.h"
#include "graph_scene.h"

#include <darkroom/error.h>

#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QStatusBar>

#include <algorithm>

namespace editor {

void MainWindow::buildExplorer(const darkroom::Registry& registry) {
    explorer_ = new ExplorerPanel(registry);
    auto* d = new QDockWidget(tr("Explorer"), this);
    d->setObjectName("explorer");
    d->setWidget(explorer_);
    addDockWidget(Qt::BottomDockWidgetArea, d);
    tabifyDockWidget(dock("graph"), d);
    d->hide();  // until a database is opened
    dock("graph")->raise();  // hiding the tab made current by tabifying raised the log
    connect(explorer_, &ExplorerPanel::picked, this, [this](std::size_t item) { cinema_->selectEntry(item); });
    connect(explorer_, &ExplorerPanel::stateChanged, this, &MainWindow::saveExplorerState);
    connect(explorer_, &ExplorerPanel::message, this, [this](const QString& m) {
        statusBar()->showMessage(m, 10000);
        logMessage(m);
    });
    connect(cinema_, &CinemaPanel::entryChosen, this, [this] {
        if (explorer_->hasDatabase()) explorer_->setCurrent(cinema_->currentEntry());
    });
    // What "Pipeline output" evaluates follows the graph and the shown node,
    // once the hand rests (each change makes every thumbnail again).
    explorerPipelineTimer_.setSingleShot(true);
    explorerPipelineTimer_.setInterval(400);
    connect(&explorerPipelineTimer_, &QTimer::timeout, this, &MainWindow::updateExplorerPipeline);
    connect(doc_, &Document::changed, this, [this] {
        syncExplorerFromDocument();
        explorerPipelineTimer_.start();
    });
}

QString MainWindow::explorerReader() const {
    if (!explorer_->hasDatabase()) return {};
    const QString want = QFileInfo(QString::fromStdString(explorer_->database())).absoluteFilePath();
    const QString selected = scene_->selectedNode();
    QString found;
    for (const auto& n : doc_->graph().nodes()) {
        if (n.type != "CinemaReader") continue;
        const darkroom::Value* db = n.parameter("database");
        if (!db || absoluteInput(QString::fromStdString(db->asString())) != want) continue;
        const QString name = QString::fromStdString(n.name);
        if (name == selected) return name;
        if (found.isEmpty()) found = name;
    }
    return found;
}

void MainWindow::saveExplorerState() {
    const QString reader = explorerReader();
    if (reader.isEmpty()) {
        statusBar()->showMessage(tr("No CinemaReader reads this database: the explorer's selection is not saved"), 8000);
        return;
    }
    const std::string text = toYaml(explorer_->state());
    if (explorerText(*doc_->graph().node(reader.toStdString())) == text) return;
    const QString err = doc_->edit(tr("Explorer selection"), [&](darkroom::Graph& g) {
        setExplorerText(g, reader.toStdString(), text);
    });
    if (!err.isEmpty()) logMessage(err);
}

void MainWindow::syncExplorerFromDocument() {
    // Undo and redo change the saved selection: the explorer follows.
    const QString reader = explorerReader();
    if (reader.isEmpty()) return;
    const std::string text = explorerText(*doc_->graph().node(reader.toStdString()));
    if (text.empty() || text == toYaml(explorer_->state())) return;
    try {
        explorer_->setState(parseExplorerState(text));
    } catch (const std::exception& e) {
        logMessage(tr("%1: %2").arg(reader, QString::fromUtf8(e.what())));
    }
}

void MainWindow::restoreExplorer() {
    // The first CinemaReader that saved an explorer selection.
    for (const auto& n : doc_->graph().nodes()) {
        const std::string text = explorerText(n);
        const darkroom::Value* db = n.parameter("database");
        if (n.type != "CinemaReader" || text.empty() || !db) continue;
        const QString name = QString::fromStdString(n.name);
        ExplorerState state;
        try {
            state = parseExplorerState(text);
        } catch (const std::exception& e) {
            logMessage(tr("%1 (node '%2'): %3").arg(doc_->path(), name, QString::fromUtf8(e.what())));
            return;
        }
        const QString path = absoluteInput(QString::fromStdString(db->asString()));
        const darkroom::Value* entry = n.parameter("entry");
        const darkroom::Value* parameters = n.parameter("parameters");
        if (!openCinema(path, entry ? entry->asInt() : -1,
                        parameters ? QString::fromStdString(parameters->asString()) : QString()))
            return;
        std::vector<std::string> problems;
        explorer_->setState(state, &problems);
        for (const auto& p : problems) logMessage(tr("%1 (node '%2'): %3").arg(doc_->path(), name, QString::fromStdString(p)));
        updateExplorerPipeline();
        return;
    }
}

void MainWindow::updateExplorerPipeline() {
    if (!explorer_->hasDatabase()) return;
    const QString reader = explorerReader();
    PipelineThumbnails spec;
    spec.reader = reader.toStdString();
    spec.node = shownTarget_.toStdString();
    spec.port = shownPort_.toStdString();
    spec.inputBase = doc_->folder().toStdString();
    const auto up = upstreamOf(doc_->graph(), spec.node);
    // Only a shown output that depends on the reader shades the entries.
    const bool shades = !reader.isEmpty() && !spec.port.empty() && !waiting_ &&
                        std::find(up.begin(), up.end(), spec.reader) != up.end();
    explorer_->setPipeline(shades ? std::make_shared<const darkroom::Graph>(doc_->graph()) : nullptr, spec);
}

}  // namespace editor
