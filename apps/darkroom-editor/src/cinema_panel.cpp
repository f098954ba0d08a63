#include "cinema_panel.h"

#include <darkroom/data/cinema/composable.h>
#include <darkroom/core/registry.h>

#include <QApplication>
#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QListWidget>
#include <QPointer>
#include <QSlider>
#include <QThreadPool>
#include <QVBoxLayout>

namespace editor {
namespace {
constexpr int kThumb = 72;
constexpr std::size_t kMaxThumbs = 500;  // beyond this the list is text only
}  // namespace

CinemaPanel::CinemaPanel(const darkroom::Registry& registry, QWidget* parent) : QWidget(parent), registry_(registry) {
    auto* lay = new QVBoxLayout(this);
    title_ = new QLabel(tr("No database open (File > Open Cinema database, or drop a .cdb here)"));
    title_->setWordWrap(true);
    lay->addWidget(title_);
    form_ = new QFormLayout;
    lay->addLayout(form_);
    list_ = new QListWidget;
    list_->setViewMode(QListView::IconMode);
    list_->setIconSize(QSize(kThumb, kThumb));
    list_->setGridSize(QSize(kThumb + 24, kThumb + 2 * fontMetrics().height() + 8));  // room for two lines of label
    list_->setWordWrap(true);
    list_->setResizeMode(QListView::Adjust);
    list_->setMovement(QListView::Static);
    list_->setUniformItemSizes(true);
    lay->addWidget(list_, 1);
    connect(list_, &QListWidget::currentRowChanged, this, [this](int r) {
        if (!updating_ && r >= 0) selectEntry(std::size_t(r));
    });
}

CinemaPanel::~CinemaPanel() {
    if (stop_) *stop_ = true;
}

QWidget* CinemaPanel::control(const QString& column) const {
    for (const auto& [c, w] : controls_)
        if (db_ && QString::fromStdString(db_->columns()[c].name) == column) return w;
    return nullptr;
}

std::optional<std::size_t> CinemaPanel::entryOfRow(std::size_t row) const {
    for (std::size_t e = 0; e < entries_.size(); ++e) {
        // In a composable image set an entry is a layer of several rows.
        const bool inEntry = composable_ ? db_->cell(row, db_->column("CISLayer")) ==
                                                   db_->cell(entries_[e].row, db_->column("CISLayer")) &&
                                               db_->cell(row, db_->column("CISImage")) ==
                                                   db_->cell(entries_[e].row, db_->column("CISImage"))
                                         : entries_[e].row == row;
        if (inEntry) return e;
    }
    return std::nullopt;
}

std::size_t CinemaPanel::firstEntry(std::int64_t selectRow, const QString& selectParameters) const {
    std::optional<std::size_t> e;
    if (selectRow >= 0 && std::size_t(selectRow) < db_->rowCount()) {
        e = entryOfRow(std::size_t(selectRow));
    } else if (!selectParameters.isEmpty()) {
        try {
            const auto rows = db_->selectWhere(selectParameters.toStdString());
            if (!rows.empty()) e = entryOfRow(rows.front());
        } catch (const std::exception&) {
            // Not a selection of this database: the first entry, as with none.
        }
    }
    return e.value_or(0);
}

bool CinemaPanel::open(const QString& path, QString* error, std::int64_t selectRow, const QString& selectParameters) {
    std::vector<CinemaEntry> entries;
    try {
        auto db = darkroom::CinemaDatabase::open(path.toStdString());
        entries = cinemaEntries(db);
        db_ = std::move(db);
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    if (stop_) *stop_ = true;
    entries_ = std::move(entries);
    composable_ = darkroom::isComposableImageSet(*db_);
    failures_ = 0;
    while (form_->rowCount()) form_->removeRow(0);
    controls_.clear();
    title_->setText(tr("%1: %2 entries%3")
                        .arg(QFileInfo(QString::fromStdString(db_->path())).fileName())
                        .arg(entries_.size())
                        .arg(composable_ ? tr(" (layers of a composable image set)") : QString()));
    for (std::size_t c : db_->parameterColumns()) {
        const auto& col = db_->columns()[c];
        // In a composable image set the CIS columns describe channels and
        // layers; the browser's entries are layers, chosen by the others.
        if (composable_ && QString::fromStdString(col.name).startsWith(QLatin1String("CIS"))) continue;
        QWidget* w;
        QWidget* row = nullptr;
        if (col.numeric && col.distinct.size() > 1) {
            auto* s = new QSlider(Qt::Horizontal);
            s->setRange(0, int(col.distinct.size()) - 1);
            s->setPageStep(1);
            // The value beside the slider, readable, wide enough for the
            // longest one so the slider does not jump.
            auto* value = new QLabel;
            value->setObjectName(QStringLiteral("value:") + QString::fromStdString(col.name));
            QStringList values;
            int wide = 0;
            for (const auto& d : col.distinct) {
                values << readableValue(d);
                wide = std::max(wide, fontMetrics().horizontalAdvance(values.back()));
            }
            value->setMinimumWidth(wide + 4);
            value->setAlignment(Qt::AlignRight | Qt::AlignVCenter);
            connect(s, &QSlider::valueChanged, value, [value, values](int i) { value->setText(values.value(i)); });
            value->setText(values.front());
            connect(s, &QSlider::valueChanged, this, &CinemaPanel::controlsChanged);
            row = new QWidget;
            auto* h = new QHBoxLayout(row);
            h->setContentsMargins(0, 0, 0, 0);
            h->addWidget(s, 1);
            h->addWidget(value);
            w = s;
        } else {
            auto* b = new QComboBox;
            for (const auto& v : col.distinct) b->addItem(readableValue(v));
            connect(b, &QComboBox::currentIndexChanged, this, &CinemaPanel::controlsChanged);
            w = b;
        }
        controls_.emplace_back(c, w);
        form_->addRow(QString::fromStdString(col.name), row ? row : w);
    }
    updating_ = true;
    list_->clear();
    // A blank stand-in until the thumbnail arrives: items keep one size.
    QPixmap blank(kThumb, kThumb);
    blank.fill(QColor(60, 60, 64));
    const QIcon waiting(blank);
    for (std::size_t e = 0; e < entries_.size(); ++e) {
        auto* item = new QListWidgetItem(entries_[e].label, list_);
        item->setToolTip(entries_[e].parameters);
        if (e < kMaxThumbs) item->setIcon(waiting);
    }
    updating_ = false;
    startThumbnails();
    selectEntry(firstEntry(selectRow, selectParameters));
    return true;
}

void CinemaPanel::selectEntry(std::size_t entry) {
    if (!db_ || entry >= entries_.size()) return;
    entry_ = entry;
    updating_ = true;
    const std::size_t row = entries_[entry].row;
    for (auto& [c, w] : controls_) {
        const auto& col = db_->columns()[c];
        const int i = int(std::find(col.distinct.begin(), col.distinct.end(), db_->cell(row, c)) - col.distinct.begin());
        if (auto* s = qobject_cast<QSlider*>(w)) s->setValue(i);
        else if (auto* b = qobject_cast<QComboBox*>(w)) b->setCurrentIndex(i);
    }
    list_->setCurrentRow(int(entry));
    updating_ = false;
    emit entryChosen(QString::fromStdString(db_->path()), qint64(row));
}

void CinemaPanel::controlsChanged() {
    if (updating_ || !db_) return;
    std::vector<darkroom::CinemaConstraint> q;
    for (auto& [c, w] : controls_) {
        const auto& col = db_->columns()[c];
        int i = -1;
        if (auto* s = qobject_cast<QSlider*>(w)) i = s->value();
        else if (auto* b = qobject_cast<QComboBox*>(w)) i = b->currentIndex();
        if (i >= 0 && std::size_t(i) < col.distinct.size()) q.push_back({col.name, col.distinct[std::size_t(i)]});
    }
    try {
        // The same matching as CinemaReader's `parameters` (numbers snap).
        if (const auto e = entryOfRow(db_->find(q).row)) selectEntry(*e);
    } catch (const std::exception& e) {
        // A combination the sampling does not contain: say so, keep the entry.
        title_->setText(QString::fromStdString(e.what()));
    }
}

void CinemaPanel::startThumbnails() {
    stop_ = std::make_shared<std::atomic<bool>>(false);
    std::vector<std::size_t> rows;
    for (std::size_t e = 0; e < std::min(entries_.size(), kMaxThumbs); ++e) rows.push_back(entries_[e].row);
    QPointer<CinemaPanel> self(this);
    auto stop = stop_;
    const darkroom::Registry* registry = &registry_;
    const std::string database = db_->path();
    QThreadPool::globalInstance()->start([self, stop, rows, registry, database] {
        CinemaEntryReader reader(*registry, database);
        for (std::size_t e = 0; e < rows.size() && !*stop; ++e) {
            QImage thumb;
            QString problem;
            try {
                thumb = thumbnail(*reader.read(rows[e]), kThumb);
            } catch (const std::exception& x) {
                problem = QString::fromStdString(x.what());
            }
            // Posted to the application object: the panel may be gone by now.
            QMetaObject::invokeMethod(qApp, [self, stop, e, thumb, problem] {
                if (!self || *stop) return;
                QListWidgetItem* item = self->list_->item(int(e));
                if (!item) return;
                if (!thumb.isNull()) item->setIcon(QIcon(QPixmap::fromImage(thumb)));
                item->setData(Qt::UserRole, !thumb.isNull());  // the thumbnail (not the stand-in) is shown
                if (!problem.isEmpty()) {
                    ++self->failures_;
                    item->setToolTip(item->toolTip() + QStringLiteral("\n") + problem);
                }
            }, Qt::QueuedConnection);
        }
    });
}

}  // namespace editor
