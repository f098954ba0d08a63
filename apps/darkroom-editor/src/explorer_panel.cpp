#include "explorer_panel.h"

#include "image_grid.h"
#include "parallel_coords.h"
#include "thumbnail_cache.h"

#include <darkroom/core/pipeline.h>

#include <QClipboard>
#include <QComboBox>
#include <QGuiApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QLocale>
#include <QSplitter>
#include <QStandardItemModel>
#include <QThread>
#include <QToolButton>
#include <QVBoxLayout>

namespace editor {
namespace {

constexpr int kThumb = 96;
constexpr std::size_t kCacheBytes = std::size_t(96) << 20;  // about 2,600 thumbnails of 96 x 96

// Background threads for thumbnails: leave a core to the interface and
// the live evaluation.
int thumbnailThreads() { return std::clamp(QThread::idealThreadCount() - 1, 1, 4); }

// What a pipeline thumbnail depends on: the graph without the reader's
// entry and without layout, and what is shown.
std::string pipelineKey(const darkroom::Graph& graph, const PipelineThumbnails& spec) {
    darkroom::Graph g = graph;
    for (const auto& n : graph.nodes()) g.clearExtras(n.name);
    if (g.node(spec.reader))
        for (const char* choice : {"entry", "parameters"}) g.clearParameter(spec.reader, choice);
    return darkroom::serializePipeline(g) + "|" + spec.node + "." + spec.port + "|" + spec.inputBase;
}

}  // namespace

ExplorerPanel::ExplorerPanel(const darkroom::Registry& registry, QWidget* parent)
    : QWidget(parent), registry_(registry), cache_(new ThumbnailCache(thumbnailThreads(), kCacheBytes, this)) {
    auto* lay = new QVBoxLayout(this);
    lay->setContentsMargins(2, 2, 2, 2);
    auto* bar = new QHBoxLayout;
    count_ = new QLabel(tr("No database open (File > Open Cinema database)"));
    sort_ = new QComboBox;
    sort_->setToolTip(tr("Sort the grid by a column"));
    descending_ = new QToolButton;
    descending_->setObjectName("descending");
    descending_->setCheckable(true);
    descending_->setText(QStringLiteral("↓"));
    descending_->setToolTip(tr("Descending"));
    show_ = new QComboBox;
    show_->addItems({tr("Raw product"), tr("Pipeline output")});
    show_->setToolTip(tr("What the grid shows for each entry: the product as CinemaReader reads it, or what the "
                         "pipeline makes of it (the node shown in the render view)"));
    auto* clear = new QToolButton;
    clear->setText(tr("Clear brushes"));
    auto* copy = new QToolButton;
    copy->setText(tr("Copy where-clause"));
    copy->setToolTip(tr("Copy the selection as SQL for darkroom run --foreach ... --where"));
    bar->addWidget(count_, 1);
    bar->addWidget(new QLabel(tr("Sort by")));
    bar->addWidget(sort_);
    bar->addWidget(descending_);
    bar->addWidget(new QLabel(tr("Show")));
    bar->addWidget(show_);
    bar->addWidget(clear);
    bar->addWidget(copy);
    lay->addLayout(bar);
    auto* split = new QSplitter(Qt::Horizontal);
    plot_ = new ParallelCoordinates;
    grid_ = new ImageGrid;
    split->addWidget(plot_);
    split->addWidget(grid_);
    split->setStretchFactor(0, 1);
    split->setStretchFactor(1, 1);
    split->setSizes({550, 450});  // the plot a little wider; kept in proportion on resize
    lay->addWidget(split, 1);

    connect(plot_, &ParallelCoordinates::brushing, this, &ExplorerPanel::selectionChanged);
    connect(plot_, &ParallelCoordinates::brushed, this, &ExplorerPanel::stateChanged);
    connect(plot_, &ParallelCoordinates::picked, this, &ExplorerPanel::onPicked);
    connect(grid_, &ImageGrid::picked, this, &ExplorerPanel::onPicked);
    connect(clear, &QToolButton::clicked, this, [this] {
        model_.setBrushes({});
        plot_->selectionChanged();
        selectionChanged();
        emit stateChanged();
    });
    connect(copy, &QToolButton::clicked, this, &ExplorerPanel::copyWhereClause);
    auto sortChanged = [this] {
        if (updating_) return;
        model_.setSort(sort_->currentIndex() - 1, descending_->isChecked());
        plot_->selectionChanged();  // polylines are coloured by the sorted column
        grid_->modelChanged(true);
        emit stateChanged();
    };
    connect(sort_, &QComboBox::currentIndexChanged, this, sortChanged);
    connect(descending_, &QToolButton::toggled, this, sortChanged);
    connect(show_, &QComboBox::currentIndexChanged, this, [this](int i) {
        if (updating_) return;
        setShowsPipeline(i == 1);
        emit stateChanged();
    });
}

ExplorerPanel::~ExplorerPanel() = default;

void ExplorerPanel::setDatabase(const darkroom::CinemaDatabase& db, const std::vector<CinemaEntry>& entries) {
    db_ = db;
    database_ = db.path();
    model_ = ExplorerModel(db, entries);
    rows_.clear();
    QStringList labels;
    for (const auto& e : entries) {
        rows_.push_back(e.row);
        labels << e.label;
    }
    current_.reset();
    {
        const QSignalBlocker b1(sort_), b2(descending_);
        sort_->clear();
        sort_->addItem(tr("database order"));
        for (const auto& a : model_.axes()) sort_->addItem(QString::fromStdString(a.name));
        descending_->setChecked(false);
    }
    restartThumbnails();
    plot_->setModel(&model_);
    grid_->setModel(&model_, cache_, labels);
    updateCount();
}

void ExplorerPanel::setPipeline(std::shared_ptr<const darkroom::Graph> graph, const PipelineThumbnails& spec) {
    PipelineThumbnails s = spec;
    const std::string key = graph ? pipelineKey(*graph, s) : std::string();
    if (auto* items = qobject_cast<QStandardItemModel*>(show_->model()))
        items->item(1)->setEnabled(bool(graph));  // nothing to shade the entries with: off
    if (key == pipelineKey_) return;
    pipelineKey_ = key;
    pipeline_ = std::move(graph);
    s.graph = pipeline_;
    pipelineSpec_ = s;
    if (pipelineMode_) restartThumbnails();
}

void ExplorerPanel::restartThumbnails() {
    if (database_.empty()) return;
    if (pipelineMode_ && pipeline_)
        cache_->setSource(pipelineThumbnails(pipelineSpec_, rows_), kThumb);
    else
        cache_->setSource(productThumbnails(registry_, database_, rows_), kThumb);
    grid_->viewport()->update();
}

void ExplorerPanel::setShowsPipeline(bool on) {
    if (on == pipelineMode_) return;
    pipelineMode_ = on;
    {
        const QSignalBlocker b(show_);
        show_->setCurrentIndex(on ? 1 : 0);
    }
    restartThumbnails();
}

void ExplorerPanel::setCurrent(std::optional<std::size_t> item) {
    current_ = item;
    plot_->setCurrent(item);
    grid_->setCurrent(item);
}

void ExplorerPanel::onPicked(std::size_t item) {
    setCurrent(item);
    emit picked(item);
}

void ExplorerPanel::selectionChanged() {
    grid_->modelChanged();
    updateCount();
}

void ExplorerPanel::updateCount() {
    const QLocale l;
    count_->setText(model_.brushes().empty()
                        ? tr("%1 entries").arg(l.toString(qulonglong(model_.size())))
                        : tr("%1 of %2 entries selected").arg(l.toString(qulonglong(model_.selectedCount())),
                                                              l.toString(qulonglong(model_.size()))));
}

ExplorerState ExplorerPanel::state() const { return captureState(model_, pipelineMode_); }

void ExplorerPanel::setState(const ExplorerState& s, std::vector<std::string>* problems) {
    applyState(model_, s, problems);
    {
        const QSignalBlocker b1(sort_), b2(descending_);
        sort_->setCurrentIndex(model_.sortAxis() + 1);
        descending_->setChecked(model_.descending());
    }
    setShowsPipeline(s.pipeline && pipeline_);
    plot_->selectionChanged();
    grid_->modelChanged(true);
    updateCount();
}

QString ExplorerPanel::whereClause() const {
    if (!db_ || model_.brushes().empty()) return {};
    const std::string clause = model_.whereClause();
    // What --where will run: the database's own query. Should SQLite read a
    // decimal end a hair off, the ends halfway to the neighbouring values
    // select the same rows whatever the rounding.
    try {
        if (db_->query(clause) == model_.selectedRows()) return QString::fromStdString(clause);
        return QString::fromStdString(model_.whereClause(true));
    } catch (const std::exception&) {
        return QString::fromStdString(model_.whereClause(true));
    }
}

void ExplorerPanel::copyWhereClause() {
    const QString clause = whereClause();
    if (clause.isEmpty()) {
        emit message(tr("No brushes: every entry is selected, no --where needed"));
        return;
    }
    QGuiApplication::clipboard()->setText(clause);
    emit message(tr("Copied the where-clause of %1 rows: %2").arg(model_.selectedRows().size()).arg(clause));
}

}  // namespace editor
