#include "main_window.h"

#include "autosave.h"

#include "cinema_panel.h"
#include "document.h"
#include "evaluation.h"
#include "evaluator_adapter.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "layout.h"
#include "node_item.h"
#include "palette.h"
#include "quick_add.h"
#include "render_view.h"

#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFileInfo>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStatusBar>
#include <QToolButton>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {

MainWindow::MainWindow(const darkroom::Registry& registry, const darkroom::Diagnostics& pluginProblems,
                       QWidget* parent)
    : QMainWindow(parent), doc_(new Document(registry, this)), eval_(new Evaluation(this)) {
    setAcceptDrops(true);
    setDockNestingEnabled(true);
    autosave_ = new Autosave(doc_, this);
    scene_ = new GraphScene(doc_, this);
    graphView_ = new GraphView(scene_);

    QToolButton* fit = buildRenderPane();
    buildDocks(registry);
    probe_ = new QLabel;
    timing_ = new QLabel;
    statusBar()->addWidget(probe_, 1);
    statusBar()->addPermanentWidget(timing_);
    for (const auto& d : pluginProblems) logMessage(QString::fromStdString(d.str()));
    logMessage(tr("%1 filter types from %2 plugins").arg(registry.filters().size()).arg(registry.plugins().size()));
    connectParts(fit);

    buildMenus();
    updateTitle();
    // Defaults: a render view well over half the window, a graph strip
    // tall enough for a row of nodes at a readable zoom.
    resize(1560, 960);
    // The saved size now; the dock layout once the window has that size
    // (restoring it earlier lays the docks out for the default size).
    QSettings s;
    if (s.value("layout/version").toInt() == kLayoutVersion) restoreGeometry(s.value("layout/geometry").toByteArray());
}

// The render view with its layer and channel choosers and Fit button (returned).
QToolButton* MainWindow::buildRenderPane() {
    auto* renderPane = new QWidget;
    auto* rl = new QVBoxLayout(renderPane);
    rl->setContentsMargins(0, 0, 0, 0);
    rl->setSpacing(2);
    auto* bar = new QHBoxLayout;
    bar->setContentsMargins(4, 2, 4, 0);
    channel_ = new QComboBox;
    channel_->setMinimumContentsLength(14);
    // Only a layered buffer (several surfaces per pixel) offers a layer.
    layer_ = new QComboBox;
    layer_->setObjectName("layerChooser");
    layer_->setToolTip(tr("Layer of a layered buffer: the front-to-back composite of its colour, or one layer"));
    layer_->hide();
    auto* fit = new QToolButton;
    fit->setText(tr("Fit"));
    bar->addWidget(new QLabel(tr("Show:")));
    bar->addWidget(layer_);
    bar->addWidget(channel_);
    bar->addWidget(fit);
    bar->addStretch(1);
    rl->addLayout(bar);
    render_ = new RenderView;
    rl->addWidget(render_, 1);
    setCentralWidget(renderPane);

    return fit;
}

// The graph, log, palette and Cinema docks, the quick-add box and the explorer.
void MainWindow::buildDocks(const darkroom::Registry& registry) {
    // The bottom docks span the whole width: the graph is wide and short.
    setCorner(Qt::BottomLeftCorner, Qt::BottomDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::BottomDockWidgetArea);
    auto* gd = new QDockWidget(tr("Graph"), this);
    gd->setObjectName("graph");
    gd->setWidget(graphView_);
    addDockWidget(Qt::BottomDockWidgetArea, gd);
    log_ = new QPlainTextEdit;
    log_->setReadOnly(true);
    log_->setMaximumBlockCount(2000);
    auto* ld = new QDockWidget(tr("Log"), this);
    ld->setObjectName("log");
    ld->setWidget(log_);
    addDockWidget(Qt::BottomDockWidgetArea, ld);
    tabifyDockWidget(gd, ld);
    gd->raise();
    palette_ = new Palette(registry);
    auto* pd = new QDockWidget(tr("Palette"), this);
    pd->setObjectName("palette");
    pd->setWidget(palette_);
    addDockWidget(Qt::LeftDockWidgetArea, pd);
    cinema_ = new CinemaPanel(registry);
    auto* cd = new QDockWidget(tr("Cinema"), this);
    cd->setObjectName("cinema");
    cd->setWidget(cinema_);
    addDockWidget(Qt::RightDockWidgetArea, cd);
    cd->hide();  // until a database is opened
    quickAdd_ = new QuickAdd(registry, this);
    buildExplorer(registry);

}

// What the parts tell each other.
void MainWindow::connectParts(QToolButton* fit) {
    connect(palette_, &Palette::addRequested, this, [this](const QString& t) { addNode(t); });
    connect(graphView_, &GraphView::quickAddRequested, this, [this](QPoint at) {
        const QPointF scenePos = graphView_->mapToScene(at);
        quickAdd_->setProperty("scenePos", scenePos);
        quickAdd_->popup(graphView_->viewport()->mapToGlobal(at));
    });
    connect(quickAdd_, &QuickAdd::chosen, this, [this](const QString& type) {
        addNode(type, quickAdd_->property("scenePos").toPointF());
        graphView_->setFocus();
    });
    connect(scene_, &GraphScene::message, this, [this](const QString& m) {
        statusBar()->showMessage(m, 8000);
        logMessage(m);
    });
    connect(scene_, &GraphScene::interaction, eval_, &Evaluation::setInteracting);
    connect(scene_, &QGraphicsScene::selectionChanged, this, &MainWindow::scheduleEvaluation);
    connect(doc_, &Document::changed, this, &MainWindow::scheduleEvaluation);
    connect(doc_, &Document::pathChanged, this, &MainWindow::updateTitle);
    connect(doc_->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(eval_, &Evaluation::finished, this, &MainWindow::onEvaluated);
    connect(eval_, &Evaluation::started, this, [this] {
        if (timing_->text().isEmpty()) timing_->setText(tr("evaluating…"));
    });
    connect(render_, &RenderView::probed, probe_, &QLabel::setText);
    connect(render_, &RenderView::presented, this, [this](std::uint64_t tag) {
        const auto it = tags_.find(tag);
        if (it == tags_.end()) return;
        const auto [generation, level] = it->second;
        tags_.erase(tags_.begin(), std::next(it));
        eval_->framePresented(generation, level);  // steers the preview size
        emit framePresented(generation, level);
    });
    connect(render_, &RenderView::modesChanged, this, [this](const QStringList& modes, const QString& cur) {
        QSignalBlocker b(channel_);
        channel_->clear();
        channel_->addItems(modes);
        channel_->setCurrentText(cur);
    });
    connect(channel_, &QComboBox::currentTextChanged, render_, &RenderView::setMode);
    connect(render_, &RenderView::layerChoicesChanged, this, [this](const QStringList& choices, const QString& cur) {
        QSignalBlocker b(layer_);
        layer_->clear();
        layer_->addItems(choices);
        layer_->setCurrentText(cur);
        layer_->setVisible(!choices.isEmpty());
    });
    connect(layer_, &QComboBox::currentTextChanged, render_, &RenderView::setLayerChoice);
    connect(fit, &QToolButton::clicked, render_, &RenderView::fit);
    connect(cinema_, &CinemaPanel::entryChosen, this, &MainWindow::onEntryChosen);

}

void MainWindow::showEvent(QShowEvent* e) {
    QMainWindow::showEvent(e);
    if (shownOnce_) return;
    shownOnce_ = true;
    restored_ = restoreLayout();
    // Default proportions, for the size the window really got: the graph a
    // strip of about a third of the height, the palette narrow.
    if (!restored_) {
        resizeDocks({dock("palette")}, {std::max(180, width() / 8)}, Qt::Horizontal);
        resizeDocks({dock("graph")}, {std::max(220, height() * 3 / 8)}, Qt::Vertical);
    }
}

MainWindow::~MainWindow() {
    // ~QWidget deletes the children before ~QObject drops their connections:
    // whatever they emit while they go would call back into this
    // half-destroyed window (the scene's items change the selection, a
    // use-after-free valgrind showed; the document's undo stack, cleared as
    // it goes, says it is clean, and updateTitle ran on a mere QWidget:
    // UBSan and Qt's debug build caught it, tests/gui/test_editor_close.cpp).
    // So every connection into this window ends here: its descendants', and
    // the undo stack's (a member of the document, not a child).
    for (QObject* child : findChildren<QObject*>()) child->disconnect(this);
    doc_->undoStack()->disconnect(this);
}

QDockWidget* MainWindow::dock(const QString& objectName) const {
    return findChild<QDockWidget*>(objectName, Qt::FindDirectChildrenOnly);
}

void MainWindow::logMessage(const QString& text) { log_->appendPlainText(text); }

QString MainWindow::frameText() const { return timing_->text(); }

QString MainWindow::addNode(const QString& type, std::optional<QPointF> scenePos) {
    const QString name = doc_->uniqueName(type);
    // Right of the existing nodes, so a new node never hides another's ports.
    const QRectF used = scene_->itemsBoundingRect();
    QPointF at = scenePos ? *scenePos - QPointF(NodeItem::width() / 2, 12)
                 : doc_->graph().nodes().empty()
                     ? graphView_->mapToScene(graphView_->viewport()->rect().center()) - QPointF(135, 40)
                     : QPointF(used.right() + 60, used.top() + 22);
    const QString err = doc_->edit(tr("Add %1").arg(name), [&](darkroom::Graph& g) {
        setNodePosition(g, g.addNode(name.toStdString(), type.toStdString()).name, at);
    });
    if (!err.isEmpty()) {
        logMessage(err);
        statusBar()->showMessage(err, 8000);
        return {};
    }
    scene_->clearSelection();
    if (NodeItem* item = scene_->nodeItem(name)) {
        item->setSelected(true);
        if (!scenePos) graphView_->ensureVisible(item);  // at the cursor it is in view already
    }
    return name;
}

void MainWindow::scheduleEvaluation() {
    const darkroom::Graph& g = doc_->graph();
    QString node = scene_->selectedNode();
    if (node.isEmpty() && g.node(shownNode_.toStdString())) node = shownNode_;
    if (node.isEmpty()) {
        // Nothing chosen yet: what the pipeline writes (the last output node
        // fed an image), else the last node in dependency order with an
        // image output.
        QString sink;
        try {
            const std::vector<std::string> sinks = g.sinks();
            for (const auto& n : g.topologicalOrder()) {
                const auto* x = g.node(n);
                for (const auto& o : g.ports(*x).outputs)
                    if (o.isImage()) node = QString::fromStdString(n);
                if (std::find(sinks.begin(), sinks.end(), n) != sinks.end())
                    for (const auto& e : g.edgesInto(n)) {
                        const auto* up = g.node(e.from.node);
                        const auto* spec = up && !up->placeholder ? g.ports(*up).output(e.from.port) : nullptr;
                        if (spec && spec->isImage()) sink = QString::fromStdString(n);
                    }
            }
        } catch (const std::exception&) {
        }
        if (!sink.isEmpty()) node = sink;
    }
    const darkroom::Node* n = g.node(node.toStdString());
    waiting_ = false;
    render_->setMessage({}, false);
    if (!n) {
        scene_->setWaiting({});
        render_->setImage(nullptr);
        scene_->setTimings({}, false);
        shownNode_.clear();
        return;
    }
    // A node without image outputs (a writer) shows what flows into it.
    QString target = node, port;
    for (const auto& o : g.ports(*n).outputs)
        if (o.isImage()) {
            port = QString::fromStdString(o.name);
            break;
        }
    if (port.isEmpty())
        for (const auto& e : g.edgesInto(n->name)) {
            const auto* up = g.node(e.from.node);
            const auto* spec = up ? g.ports(*up).output(e.from.port) : nullptr;
            if (spec && spec->isImage()) {
                target = QString::fromStdString(e.from.node);
                port = QString::fromStdString(e.from.port);
                break;
            }
        }
    shownNode_ = node;
    if (shownTarget_ != target || shownPort_ != port) explorerPipelineTimer_.start();
    shownTarget_ = target;
    shownPort_ = port;
    if (showWaiting(node, target)) return;
    if (port.isEmpty()) {
        render_->setImage(nullptr);
        return;
    }
    // Selection and document signals often arrive together for one change;
    // asking twice would cancel a run only to start the same one again.
    const QString key = QStringLiteral("%1|%2|%3|%4").arg(g.revision()).arg(target, port, doc_->folder());
    if (key == lastRequest_ && eval_->busy()) return;
    lastRequest_ = key;
    eval_->request(g, target, port, doc_->folder());
}

QString MainWindow::absoluteInput(const QString& path) const {
    if (path.isEmpty() || !QFileInfo(path).isRelative() || doc_->folder().isEmpty())
        return QFileInfo(path).absoluteFilePath();
    return QFileInfo(QDir(doc_->folder()).filePath(path)).absoluteFilePath();
}

bool MainWindow::showWaiting(const QString& node, const QString& target) {
    std::map<QString, QString> waiting;  // node -> what it waits for
    QStringList lines;
    for (const auto& [n, input] : waitingForInput(doc_->graph(), target.toStdString())) {
        const QString line = tr("%1 (%2) is waiting for input: connect its '%3' input")
                                 .arg(QString::fromStdString(n), QString::fromStdString(doc_->graph().node(n)->type),
                                      QString::fromStdString(input));
        waiting[QString::fromStdString(n)] = line;
        lines << line;
    }
    scene_->setWaiting(waiting);
    if (waiting.empty()) return false;
    // Not a failure: nothing to evaluate yet. Results still in flight are
    // of an older graph and are not shown.
    waiting_ = true;
    lastRequest_.clear();
    render_->setImage(nullptr);
    render_->setMessage(lines.join('\n'), false);
    timing_->setText(tr("%1: waiting for input").arg(node));
    emit evaluated();
    return true;
}

void MainWindow::onEvaluated(const EvalResult& r) {
    if (waiting_) {
        emit evaluated();
        return;
    }
    if (r.level == 0) scene_->setInputChannels(r.inputChannels);
    std::map<QString, QString> errors;
    for (const auto& n : r.errorNodes) errors[n] = r.error;
    if (r.level == 0) scene_->setErrors(errors);
    if (!r.error.isEmpty()) {
        logMessage(r.error);
        statusBar()->showMessage(r.error, 8000);
        timing_->setText(tr("failed"));
        // Over the picture, where the user looks, naming the failing node
        // (the evaluator's messages usually start with it already).
        QStringList named;
        for (const auto& n : r.errorNodes)
            if (const darkroom::Node* x = doc_->graph().node(n.toStdString());
                x && !r.error.contains(QStringLiteral("node '%1'").arg(n)))
                named << tr("'%1' (%2)").arg(n, QString::fromStdString(x->type));
        render_->setMessage(named.isEmpty() ? r.error : tr("Node %1 failed: %2").arg(named.join(", "), r.error), true);
        emit evaluated();
        return;
    }
    render_->setMessage({}, false);
    tags_[++tag_] = {r.generation, r.level};
    render_->setImage(r.image, r.level, tag_);

    // Badges and the status line: what ran for this frame, and how long.
    std::map<QString, GraphScene::Timing> timings;
    QStringList ran;
    int inGraph = 0;
    for (const auto& run : r.profile.nodes) {
        const QString name = QString::fromStdString(run.node);
        if (!doc_->graph().node(run.node)) continue;  // the preview's own Resize nodes
        ++inGraph;
        timings[name] = {run.seconds, run.ran};
        if (run.ran) ran << name;
    }
    scene_->setTimings(timings, r.level > 0);
    if (r.image) {
        const QString size = QStringLiteral("%1 × %2").arg(r.image->width()).arg(r.image->height());
        const QString what = r.level > 0 ? tr("preview 1/%1, %2").arg(1 << r.level).arg(size) : size;
        QString ranText = ran.isEmpty() ? tr("all cached") : tr("ran %1 of %2: %3").arg(ran.size()).arg(inGraph).arg(ran.join(", "));
        if (ranText.size() > 90) ranText = ranText.left(88) + QStringLiteral("…");
        timing_->setText(tr("%1: %2, %3 ms · %4").arg(r.node, what).arg(r.profile.seconds * 1000.0, 0, 'f', 1).arg(ranText));
        timing_->setToolTip(ran.join(QStringLiteral("\n")));
    } else {
        timing_->clear();
    }
    emit evaluated();
}

// Whether the reader already reads `row` of the browser's database: by its
// `entry`, or, without one, by the `parameters` a pipeline was saved with.
bool MainWindow::readsRow(const darkroom::Node& reader, qint64 row) const {
    const darkroom::Value* e = reader.parameter("entry");
    if (e && e->asInt() >= 0) return e->asInt() == row;
    const darkroom::Value* p = reader.parameter("parameters");
    const darkroom::CinemaDatabase* db = cinema_->database();
    if (!p || p->asString().empty() || !db) return false;
    try {
        const auto rows = db->selectWhere(p->asString());
        return !rows.empty() && qint64(rows.front()) == row;
    } catch (const std::exception&) {
        return false;
    }
}

void MainWindow::onEntryChosen(const QString& database, qint64 row) {
    const darkroom::Graph& g = doc_->graph();
    QString reader;
    const QString sel = scene_->selectedNode();
    if (const auto* n = g.node(sel.toStdString()); n && n->type == "CinemaReader") reader = sel;
    int count = 0;
    if (reader.isEmpty())
        for (const auto& n : g.nodes())
            if (n.type == "CinemaReader") reader = QString::fromStdString(n.name), ++count;
    if (count > 1) {
        statusBar()->showMessage(tr("Several CinemaReader nodes: select the one the browser drives"), 8000);
        return;
    }
    bool add = false;
    // The reader may name the database relative to the pipeline, the
    // browser as it was opened: the same folder either way.
    const QString folder = QFileInfo(database).absoluteFilePath();
    auto readsDatabase = [&](const darkroom::Node& n) {
        const darkroom::Value* db = n.parameter("database");
        return db && absoluteInput(QString::fromStdString(db->asString())) == folder;
    };
    if (const auto* n = g.node(reader.toStdString())) {
        // Already reading that entry (a pipeline opened with its database):
        // nothing to edit, the document stays as loaded.
        if (readsDatabase(*n) && readsRow(*n, row)) return;
    }
    if (reader.isEmpty()) {
        if (!g.registry().filter("CinemaReader")) return;
        reader = doc_->uniqueName(QStringLiteral("CinemaReader"));
        add = true;
    }
    // One edit (and one evaluation) for adding the reader and pointing it at the entry.
    const std::vector<CinemaEntry>& entries = cinema_->entries();
    const QString label = cinema_->currentEntry() < entries.size() ? entries[cinema_->currentEntry()].label
                                                                   : QString::number(row);
    const QString err = doc_->edit(tr("Cinema entry %1").arg(label), [&](darkroom::Graph& gg) {
        const std::string n = reader.toStdString();
        if (add) {
            const QRectF used = scene_->itemsBoundingRect();
            setNodePosition(gg, gg.addNode(n, "CinemaReader").name,
                            gg.nodes().size() == 1 ? graphView_->mapToScene(graphView_->viewport()->rect().center()) -
                                                         QPointF(NodeItem::width() / 2, 40)
                                                   : QPointF(used.left(), used.bottom() + 60));
        }
        if (!readsDatabase(*gg.node(n))) gg.setParameter(n, "database", folder.toStdString());
        // The row replaces a choice by values the pipeline may have had.
        gg.setParameter(n, "entry", darkroom::Value(std::int64_t(row)));
        gg.clearParameter(n, "parameters");
    }, add ? QString() : QStringLiteral("cinema:") + reader);
    if (!err.isEmpty()) logMessage(err);
    if (add) {
        scene_->clearSelection();
        if (NodeItem* item = scene_->nodeItem(reader)) {
            item->setSelected(true);
            graphView_->ensureVisible(item);
        }
    }
}

}  // namespace editor
