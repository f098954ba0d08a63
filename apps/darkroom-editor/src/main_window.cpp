#include "main_window.h"

#include "cinema_panel.h"
#include "document.h"
#include "evaluation.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "layout.h"
#include "node_item.h"
#include "palette.h"
#include "render_view.h"

#include <QComboBox>
#include <QDockWidget>
#include <QHBoxLayout>
#include <QLabel>
#include <QPlainTextEdit>
#include <QSplitter>
#include <QStatusBar>
#include <QToolButton>
#include <QVBoxLayout>

namespace editor {

MainWindow::MainWindow(const darkroom::Registry& registry, const darkroom::Diagnostics& pluginProblems,
                       QWidget* parent)
    : QMainWindow(parent), doc_(new Document(registry, this)), eval_(new Evaluation(this)) {
    setAcceptDrops(true);
    scene_ = new GraphScene(doc_, this);
    graphView_ = new GraphView(scene_);

    auto* renderPane = new QWidget;
    auto* rl = new QVBoxLayout(renderPane);
    rl->setContentsMargins(0, 0, 0, 0);
    auto* bar = new QHBoxLayout;
    channel_ = new QComboBox;
    channel_->setMinimumContentsLength(14);
    auto* fit = new QToolButton;
    fit->setText(tr("Fit"));
    bar->addWidget(new QLabel(tr("Show:")));
    bar->addWidget(channel_, 1);
    bar->addWidget(fit);
    rl->addLayout(bar);
    render_ = new RenderView;
    rl->addWidget(render_, 1);
    auto* split = new QSplitter;
    split->addWidget(graphView_);
    split->addWidget(renderPane);
    split->setStretchFactor(0, 3);
    split->setStretchFactor(1, 2);
    setCentralWidget(split);

    palette_ = new Palette(registry);
    auto* pd = new QDockWidget(tr("Palette"), this);
    pd->setObjectName("palette");
    pd->setWidget(palette_);
    addDockWidget(Qt::LeftDockWidgetArea, pd);
    cinema_ = new CinemaPanel;
    auto* cd = new QDockWidget(tr("Cinema"), this);
    cd->setObjectName("cinema");
    cd->setWidget(cinema_);
    addDockWidget(Qt::RightDockWidgetArea, cd);
    log_ = new QPlainTextEdit;
    log_->setReadOnly(true);
    log_->setMaximumBlockCount(2000);
    auto* ld = new QDockWidget(tr("Log"), this);
    ld->setObjectName("log");
    ld->setWidget(log_);
    addDockWidget(Qt::BottomDockWidgetArea, ld);

    probe_ = new QLabel;
    timing_ = new QLabel;
    statusBar()->addWidget(probe_, 1);
    statusBar()->addPermanentWidget(timing_);

    for (const auto& d : pluginProblems) logMessage(QString::fromStdString(d.str()));
    logMessage(tr("%1 filter types from %2 plugins").arg(registry.filters().size()).arg(registry.plugins().size()));

    connect(palette_, &Palette::addRequested, this, [this](const QString& t) { addNode(t); });
    connect(scene_, &GraphScene::message, this, [this](const QString& m) {
        statusBar()->showMessage(m, 8000);
        logMessage(m);
    });
    connect(scene_, &QGraphicsScene::selectionChanged, this, &MainWindow::scheduleEvaluation);
    connect(doc_, &Document::changed, this, &MainWindow::scheduleEvaluation);
    connect(doc_, &Document::pathChanged, this, &MainWindow::updateTitle);
    connect(doc_->undoStack(), &QUndoStack::cleanChanged, this, &MainWindow::updateTitle);
    connect(eval_, &Evaluation::finished, this, &MainWindow::onEvaluated);
    connect(eval_, &Evaluation::started, this, [this] { timing_->setText(tr("evaluating…")); });
    connect(render_, &RenderView::probed, probe_, &QLabel::setText);
    connect(render_, &RenderView::modesChanged, this, [this](const QStringList& modes, const QString& cur) {
        QSignalBlocker b(channel_);
        channel_->clear();
        channel_->addItems(modes);
        channel_->setCurrentText(cur);
    });
    connect(channel_, &QComboBox::currentTextChanged, render_, &RenderView::setMode);
    connect(fit, &QToolButton::clicked, render_, &RenderView::fit);
    connect(cinema_, &CinemaPanel::entryChosen, this, &MainWindow::onEntryChosen);

    buildMenus();
    updateTitle();
    resize(1500, 900);
}

MainWindow::~MainWindow() {
    // ~QWidget deletes the children before ~QObject drops their connections:
    // the scene's items then change the selection and would call back into
    // this half-destroyed window (a use-after-free valgrind showed).
    scene_->disconnect(this);
    doc_->disconnect(this);
}

void MainWindow::logMessage(const QString& text) { log_->appendPlainText(text); }

QString MainWindow::addNode(const QString& type) {
    const QString name = doc_->uniqueName(type);
    // Right of the existing nodes, so a new node never hides another's ports.
    const QRectF used = scene_->itemsBoundingRect();
    const QPointF at = doc_->graph().nodes().empty()
                           ? graphView_->mapToScene(graphView_->viewport()->rect().center()) - QPointF(135, 40)
                           : QPointF(used.right() + 60, used.top());
    const QString err = doc_->edit(tr("Add %1").arg(name), [&](darkroom::Graph& g) {
        setNodePosition(g.addNode(name.toStdString(), type.toStdString()), at);
    });
    if (!err.isEmpty()) {
        logMessage(err);
        statusBar()->showMessage(err, 8000);
        return {};
    }
    scene_->clearSelection();
    if (NodeItem* item = scene_->nodeItem(name)) {
        item->setSelected(true);
        graphView_->ensureVisible(item);
    }
    return name;
}

void MainWindow::scheduleEvaluation() {
    const darkroom::Graph& g = doc_->graph();
    QString node = scene_->selectedNode();
    if (node.isEmpty() && g.node(shownNode_.toStdString())) node = shownNode_;
    if (node.isEmpty()) {
        // Nothing chosen yet: the last node in dependency order with an image output.
        try {
            for (const auto& n : g.topologicalOrder()) {
                const auto* x = g.node(n);
                for (const auto& o : g.ports(*x).outputs)
                    if (o.isImage()) node = QString::fromStdString(n);
            }
        } catch (const std::exception&) {
        }
    }
    const darkroom::Node* n = g.node(node.toStdString());
    if (!n) {
        render_->setImage(nullptr);
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

void MainWindow::onEvaluated(const EvalResult& r) {
    std::map<QString, QString> errors;
    for (const auto& n : r.errorNodes) errors[n] = r.error;
    scene_->setErrors(errors);
    if (!r.error.isEmpty()) {
        logMessage(r.error);
        statusBar()->showMessage(r.error, 8000);
        timing_->setText(tr("failed"));
    } else {
        render_->setImage(r.image);
        timing_->setText(r.image ? tr("%1: %2 x %3, %4 ms")
                                       .arg(r.node)
                                       .arg(r.image->width())
                                       .arg(r.image->height())
                                       .arg(r.seconds * 1000.0, 0, 'f', 1)
                                 : QString());
    }
    emit evaluated();
}

void MainWindow::onEntryChosen(const QString& database, const QString& parameters) {
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
    if (reader.isEmpty()) {
        if (!g.registry().filter("CinemaReader")) return;
        reader = addNode(QStringLiteral("CinemaReader"));
        if (reader.isEmpty()) return;
    }
    const QString err = doc_->edit(tr("Cinema entry %1").arg(parameters), [&](darkroom::Graph& gg) {
        const std::string n = reader.toStdString();
        const darkroom::Value* db = gg.node(n)->parameter("database");
        if (!db || QString::fromStdString(db->asString()) != database) gg.setParameter(n, "database", database.toStdString());
        gg.setParameter(n, "parameters", parameters.toStdString());
    }, QStringLiteral("cinema:") + reader);
    if (!err.isEmpty()) logMessage(err);
}

}  // namespace editor
