#include "cinema_panel.h"

#include "display.h"

#include <darkroom/framework/image_io.h>

#include <QApplication>
#include <QComboBox>
#include <QFileInfo>
#include <QFormLayout>
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

CinemaPanel::CinemaPanel(QWidget* parent) : QWidget(parent) {
    auto* lay = new QVBoxLayout(this);
    title_ = new QLabel(tr("No database open (File > Open Cinema database, or drop a .cdb here)"));
    title_->setWordWrap(true);
    lay->addWidget(title_);
    form_ = new QFormLayout;
    lay->addLayout(form_);
    list_ = new QListWidget;
    list_->setViewMode(QListView::IconMode);
    list_->setIconSize(QSize(kThumb, kThumb));
    list_->setResizeMode(QListView::Adjust);
    list_->setUniformItemSizes(true);
    lay->addWidget(list_, 1);
    connect(list_, &QListWidget::currentRowChanged, this, [this](int r) {
        if (!updating_ && r >= 0) selectRow(std::size_t(r));
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

bool CinemaPanel::open(const QString& path, QString* error) {
    try {
        db_ = darkroom::CinemaDatabase::open(path.toStdString());
    } catch (const std::exception& e) {
        if (error) *error = QString::fromStdString(e.what());
        return false;
    }
    while (form_->rowCount()) form_->removeRow(0);
    controls_.clear();
    title_->setText(tr("%1: %2 entries").arg(QFileInfo(QString::fromStdString(db_->path())).fileName())
                        .arg(db_->rowCount()));
    for (std::size_t c : db_->parameterColumns()) {
        const auto& col = db_->columns()[c];
        QWidget* w;
        if (col.numeric && col.distinct.size() > 1) {
            auto* s = new QSlider(Qt::Horizontal);
            s->setRange(0, int(col.distinct.size()) - 1);
            s->setPageStep(1);
            connect(s, &QSlider::valueChanged, this, &CinemaPanel::controlsChanged);
            w = s;
        } else {
            auto* b = new QComboBox;
            for (const auto& v : col.distinct) b->addItem(QString::fromStdString(v));
            connect(b, &QComboBox::currentIndexChanged, this, &CinemaPanel::controlsChanged);
            w = b;
        }
        controls_.emplace_back(c, w);
        form_->addRow(QString::fromStdString(col.name), w);
    }
    updating_ = true;
    list_->clear();
    for (std::size_t r = 0; r < db_->rowCount(); ++r)
        list_->addItem(QString::fromStdString(db_->entryName(r)));
    updating_ = false;
    startThumbnails();
    selectRow(0);
    return true;
}

void CinemaPanel::selectRow(std::size_t row) {
    if (!db_ || row >= db_->rowCount()) return;
    row_ = row;
    updating_ = true;
    for (auto& [c, w] : controls_) {
        const auto& col = db_->columns()[c];
        const int i = int(std::find(col.distinct.begin(), col.distinct.end(), db_->cell(row, c)) - col.distinct.begin());
        if (auto* s = qobject_cast<QSlider*>(w)) s->setValue(i);
        else if (auto* b = qobject_cast<QComboBox*>(w)) b->setCurrentIndex(i);
    }
    list_->setCurrentRow(int(row));
    updating_ = false;
    emit entryChosen(QString::fromStdString(db_->path()), QString::fromStdString(db_->formatParameters(row)));
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
        selectRow(db_->find(q).row);
    } catch (const std::exception& e) {
        // A combination the sampling does not contain: say so, keep the entry.
        title_->setText(QString::fromStdString(e.what()));
    }
}

void CinemaPanel::startThumbnails() {
    if (stop_) *stop_ = true;
    stop_ = std::make_shared<std::atomic<bool>>(false);
    std::vector<std::string> paths;
    for (std::size_t r = 0; r < std::min(db_->rowCount(), kMaxThumbs); ++r) {
        try {
            paths.push_back(db_->productPath(r));
        } catch (const std::exception&) {
            paths.emplace_back();
        }
    }
    QPointer<CinemaPanel> self(this);
    auto stop = stop_;
    QThreadPool::globalInstance()->start([self, stop, paths] {
        for (std::size_t r = 0; r < paths.size() && !*stop; ++r) {
            QImage thumb;
            try {
                const auto img = darkroom::readImage(paths[r]);
                const auto modes = displayModes(*img);
                if (!modes.isEmpty())
                    thumb = renderDisplay(*img, modes.front()).scaled(kThumb, kThumb, Qt::KeepAspectRatio,
                                                                      Qt::SmoothTransformation);
            } catch (const std::exception&) {
                continue;  // not an image readImage knows (.npz, .vti): no thumbnail
            }
            // Posted to the application object: the panel may be gone by now.
            QMetaObject::invokeMethod(qApp, [self, stop, r, thumb] {
                if (!self || *stop) return;
                if (auto* item = self->list_->item(int(r))) item->setIcon(QIcon(QPixmap::fromImage(thumb)));
            }, Qt::QueuedConnection);
        }
    });
}

}  // namespace editor
