#include "image_grid.h"

#include "explorer_model.h"
#include "thumbnail_cache.h"

#include <QHelpEvent>
#include <QKeyEvent>
#include <QPainter>
#include <QScrollBar>
#include <QToolTip>

#include <algorithm>

namespace editor {
namespace {
constexpr int kPad = 6;
}  // namespace

ImageGrid::ImageGrid(QWidget* parent) : QAbstractScrollArea(parent) {
    arrivals_.setSingleShot(true);
    arrivals_.setInterval(50);
    connect(&arrivals_, &QTimer::timeout, this, [this] {
        viewport()->update(arrived_);
        arrived_ = QRegion();
    });
    setFocusPolicy(Qt::StrongFocus);
    setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff);
    viewport()->setAttribute(Qt::WA_OpaquePaintEvent);
}

void ImageGrid::setModel(const ExplorerModel* model, ThumbnailCache* cache, QStringList labels) {
    model_ = model;
    labels_ = std::move(labels);
    if (cache_ != cache) {
        if (cache_) cache_->disconnect(this);
        cache_ = cache;
        // A picture arrived: repaint its cell if it is on screen, at most
        // every 50 ms (each frame composes the whole window, the render
        // view's OpenGL included: pictures landing one by one would cost a
        // frame each while the user scrolls).
        connect(cache_, &ThumbnailCache::ready, this, [this](std::size_t item) {
            const QRect r = cellRect(item);
            if (r.isEmpty() || !r.intersects(viewport()->rect())) return;
            arrived_ |= r;
            if (!arrivals_.isActive()) arrivals_.start();
        });
    }
    current_.reset();
    verticalScrollBar()->setValue(0);
    modelChanged();
}

void ImageGrid::modelChanged(bool showCurrent) {
    updateScrollRange();
    if (showCurrent && current_)
        if (const int p = positionOf(*current_); p >= 0) ensureVisible(std::size_t(p));
    viewport()->update();
}

QSize ImageGrid::cellSize() const {
    const int s = cache_ ? cache_->thumbnailSize() : 96;
    return {s + 2 * kPad, s + 2 * kPad + fontMetrics().height() + 2};
}

int ImageGrid::columns() const { return std::max(1, viewport()->width() / cellSize().width()); }

void ImageGrid::updateScrollRange() {
    const std::size_t n = model_ ? model_->selectedCount() : 0;
    const int rows = int((n + std::size_t(columns()) - 1) / std::size_t(columns()));
    const QSize cell = cellSize();
    verticalScrollBar()->setRange(0, std::max(0, rows * cell.height() - viewport()->height()));
    verticalScrollBar()->setPageStep(viewport()->height());
    verticalScrollBar()->setSingleStep(cell.height() / 3);
}

QRect ImageGrid::cellAt(int position) const {
    const QSize cell = cellSize();
    const int cols = columns();
    const int left = (viewport()->width() - cols * cell.width()) / 2;
    return QRect(left + (position % cols) * cell.width(), (position / cols) * cell.height() - verticalScrollBar()->value(),
                 cell.width(), cell.height());
}

int ImageGrid::positionOf(std::size_t item) const {
    if (!model_ || item >= model_->size() || !model_->isSelected(item)) return -1;
    const auto& order = model_->order();
    const auto it = std::find(order.begin(), order.end(), std::uint32_t(item));
    return it == order.end() ? -1 : int(it - order.begin());
}

QRect ImageGrid::cellRect(std::size_t item) const {
    const int p = positionOf(item);
    return p < 0 ? QRect() : cellAt(p);
}

std::optional<std::size_t> ImageGrid::itemAt(QPoint pos) const {
    if (!model_) return std::nullopt;
    const QSize cell = cellSize();
    const int cols = columns();
    const int left = (viewport()->width() - cols * cell.width()) / 2;
    const int x = pos.x() - left, y = pos.y() + verticalScrollBar()->value();
    if (x < 0 || y < 0 || x >= cols * cell.width()) return std::nullopt;
    const std::size_t p = std::size_t(y / cell.height()) * std::size_t(cols) + std::size_t(x / cell.width());
    if (p >= model_->order().size()) return std::nullopt;
    return model_->order()[p];
}

std::pair<std::size_t, std::size_t> ImageGrid::visibleRange() const {
    if (!model_) return {0, 0};
    const QSize cell = cellSize();
    const std::size_t cols = std::size_t(columns());
    const std::size_t first = std::size_t(verticalScrollBar()->value() / cell.height()) * cols;
    const std::size_t last =
        std::size_t((verticalScrollBar()->value() + viewport()->height() - 1) / cell.height() + 1) * cols;
    return {std::min(first, model_->order().size()), std::min(last, model_->order().size())};
}

std::vector<std::size_t> ImageGrid::visibleItems() const {
    const auto [first, last] = visibleRange();
    std::vector<std::size_t> out;
    for (std::size_t p = first; p < last; ++p) out.push_back(model_->order()[p]);
    return out;
}

QString ImageGrid::caption(std::size_t item) const {
    // Sorted: the value sorted by (the bar names the column); else the label.
    if (model_->sortAxis() >= 0) return model_->text(std::size_t(model_->sortAxis()), item);
    return labels_.value(int(item));
}

void ImageGrid::paintEvent(QPaintEvent*) {
    ++paints_;
    arrived_ = QRegion();  // this paint shows them
    QPainter p(viewport());
    p.fillRect(viewport()->rect(), QColor(34, 35, 38));
    if (!model_ || !cache_) return;
    const QSize cell = cellSize();
    const int s = cache_->thumbnailSize();
    std::vector<std::size_t> wanted;
    const auto [first, last] = visibleRange();
    const QFontMetrics fm = p.fontMetrics();
    for (std::size_t position = first; position < last; ++position) {
        const std::size_t item = model_->order()[position];
        const QRect r = cellAt(int(position));
        const QRect thumb(r.left() + kPad, r.top() + kPad, s, s);
        bool fresh = false;
        if (const QImage* image = cache_->find(item, &fresh)) {
            const QSize is = image->size();
            p.drawImage(QPoint(thumb.left() + (s - is.width()) / 2, thumb.top() + (s - is.height()) / 2), *image);
            if (!fresh) wanted.push_back(item);  // made by an earlier source: a new one is coming
        } else {
            p.fillRect(thumb, QColor(58, 60, 64));
            if (!cache_->problem(item).isEmpty()) {
                p.setPen(QPen(QColor(200, 70, 70), 2));
                p.drawLine(thumb.topLeft() + QPoint(s / 3, s / 3), thumb.bottomRight() - QPoint(s / 3, s / 3));
                p.drawLine(thumb.topRight() + QPoint(-s / 3, s / 3), thumb.bottomLeft() + QPoint(s / 3, -s / 3));
            } else {
                wanted.push_back(item);
            }
        }
        if (current_ && *current_ == item) {
            p.setPen(QPen(QColor(255, 176, 40), 3));
            p.setBrush(Qt::NoBrush);
            p.drawRect(thumb.adjusted(-2, -2, 2, 2));
        }
        p.setPen(QColor(210, 212, 216));
        p.drawText(QRect(r.left() + 2, thumb.bottom() + 2, cell.width() - 4, fm.height()), Qt::AlignHCenter | Qt::AlignTop,
                   fm.elidedText(caption(item), Qt::ElideRight, cell.width() - 4));
    }
    // Then the screen below, so scrolling on finds it made.
    const std::size_t ahead = std::min(model_->order().size(), last + (last - first));
    for (std::size_t position = last; position < ahead; ++position) wanted.push_back(model_->order()[position]);
    cache_->want(wanted);
}

void ImageGrid::resizeEvent(QResizeEvent* e) {
    QAbstractScrollArea::resizeEvent(e);
    updateScrollRange();
}

void ImageGrid::scrollContentsBy(int, int) {
    arrived_ = QRegion();  // cell rectangles moved; the full repaint shows them
    viewport()->update();
}

void ImageGrid::setCurrent(std::optional<std::size_t> item) {
    if (item == current_) return;
    current_ = item;
    if (current_) {
        const int p = positionOf(*current_);
        if (p >= 0) ensureVisible(std::size_t(p));
    }
    viewport()->update();
}

void ImageGrid::ensureVisible(std::size_t position) {
    const QRect r = cellAt(int(position));
    QScrollBar* sb = verticalScrollBar();
    if (r.top() < 0) sb->setValue(sb->value() + r.top());
    else if (r.bottom() > viewport()->height()) sb->setValue(sb->value() + r.bottom() - viewport()->height() + 1);
}

void ImageGrid::mousePressEvent(QMouseEvent* e) {
    const auto item = itemAt(e->position().toPoint());
    if (!item) return;
    setCurrent(*item);
    emit picked(*item);
}

void ImageGrid::keyPressEvent(QKeyEvent* e) {
    if (!model_ || model_->order().empty()) return QAbstractScrollArea::keyPressEvent(e);
    const int n = int(model_->order().size());
    const int cols = columns();
    const int rowsPerPage = std::max(1, viewport()->height() / cellSize().height());
    int p = current_ ? positionOf(*current_) : -1;
    switch (e->key()) {
    case Qt::Key_Left: p = std::max(0, p - 1); break;
    case Qt::Key_Right: p = std::min(n - 1, p + 1); break;
    case Qt::Key_Up: p = std::max(0, p - cols); break;
    case Qt::Key_Down: p = std::min(n - 1, p < 0 ? 0 : p + cols); break;
    case Qt::Key_PageUp: p = std::max(0, p - cols * rowsPerPage); break;
    case Qt::Key_PageDown: p = std::min(n - 1, p + cols * rowsPerPage); break;
    case Qt::Key_Home: p = 0; break;
    case Qt::Key_End: p = n - 1; break;
    default: return QAbstractScrollArea::keyPressEvent(e);
    }
    const std::size_t item = model_->order()[std::size_t(p)];
    setCurrent(item);
    emit picked(item);
}

bool ImageGrid::viewportEvent(QEvent* e) {
    if (e->type() == QEvent::ToolTip && model_) {
        auto* h = static_cast<QHelpEvent*>(e);
        if (const auto item = itemAt(h->pos())) {
            QString tip = labels_.value(int(*item));
            if (cache_ && !cache_->problem(*item).isEmpty()) tip += QStringLiteral("\n") + cache_->problem(*item);
            QToolTip::showText(h->globalPos(), tip, viewport());
        } else {
            QToolTip::hideText();
        }
        return true;
    }
    return QAbstractScrollArea::viewportEvent(e);
}

}  // namespace editor
