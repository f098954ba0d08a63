#include "parallel_coords.h"

#include "explorer_model.h"
#include "polyline_raster.h"

#include <QElapsedTimer>
#include <QMouseEvent>
#include <QPainter>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace editor {
namespace {

constexpr int kTop = 34, kBottom = 34, kSide = 56;
constexpr int kReach = 10;       // pixels either side of an axis that grab it
constexpr int kMissingGap = 14;  // missing values sit this far below an axis

}  // namespace

ParallelCoordinates::ParallelCoordinates(QWidget* parent) : QWidget(parent) {
    setMinimumSize(240, 160);
    setAttribute(Qt::WA_OpaquePaintEvent);
    setMouseTracking(false);
}

void ParallelCoordinates::setModel(ExplorerModel* model) {
    model_ = model;
    current_.reset();
    contextDirty_ = selectionDirty_ = true;
    update();
}

void ParallelCoordinates::selectionChanged() {
    selectionDirty_ = true;
    update();
}

void ParallelCoordinates::setCurrent(std::optional<std::size_t> item) {
    if (item == current_) return;
    current_ = item;
    update();
}

double ParallelCoordinates::axisX(std::size_t axis) const {
    const std::size_t n = model_ ? model_->axes().size() : 0;
    if (n <= 1) return width() / 2.0;
    return kSide + double(axis) * double(width() - 2 * kSide) / double(n - 1);
}

double ParallelCoordinates::yOf(double unit) const { return kTop + (1.0 - unit) * double(height() - kTop - kBottom); }

double ParallelCoordinates::unitAt(double y) const {
    return std::clamp(1.0 - (y - kTop) / double(std::max(1, height() - kTop - kBottom)), 0.0, 1.0);
}

QPoint ParallelCoordinates::pointOf(std::size_t axis, double value) const {
    return QPointF(axisX(axis), yOf(model_->axes()[axis].toUnit(value))).toPoint();
}

double ParallelCoordinates::itemY(std::size_t axis, std::size_t item) const {
    const float u = model_->unit(axis, item);
    return std::isnan(u) ? double(height() - kBottom + kMissingGap) : yOf(u);
}

void ParallelCoordinates::layoutItems() {
    ys_.assign(model_ ? model_->axes().size() : 0, {});
    for (std::size_t a = 0; a < ys_.size(); ++a) {
        ys_[a].resize(model_->size());
        for (std::size_t i = 0; i < model_->size(); ++i) ys_[a][i] = float(itemY(a, i));
    }
}

void ParallelCoordinates::resizeEvent(QResizeEvent*) { contextDirty_ = selectionDirty_ = true; }

void ParallelCoordinates::drawPolylines(QImage& target, bool selectedOnly) {
    const std::size_t axes = model_ ? model_->axes().size() : 0;
    const std::size_t n = model_ ? model_->size() : 0;
    const std::size_t shown = selectedOnly && model_ ? model_->selectedCount() : n;
    if (axes < 2 || shown == 0) {
        target = QImage(size(), QImage::Format_ARGB32_Premultiplied);
        target.fill(Qt::transparent);
        return;
    }
    std::vector<int> xs(axes);
    for (std::size_t a = 0; a < axes; ++a) xs[a] = int(std::lround(axisX(a)));
    PolylineRaster raster(width(), height(), xs);
    // Coloured by the sorted column (the grid's order), else the first axis.
    const std::size_t by = model_->sortAxis() >= 0 ? std::size_t(model_->sortAxis()) : 0;
    raster.rasterise([&](std::size_t gap, const PolylineRaster::AddSegment& add) {
        for (std::size_t i = 0; i < n; ++i) {
            if (selectedOnly && !model_->isSelected(i)) continue;
            const float t = model_->unit(by, i);
            add(ys_[gap][i], ys_[gap + 1][i], std::isnan(t) ? 0.0f : t);
        }
    }, QThread::idealThreadCount());
    // Dense plots stay readable: the more lines, the fainter each.
    target = selectedOnly ? raster.toImage(std::max(0.2f, float(shown) / 800.0f), true, 0, 235)
                          : raster.toImage(std::max(0.5f, float(shown) / 200.0f), false, qRgb(150, 155, 165), 110);
}

void ParallelCoordinates::renderContext() {
    contextDirty_ = false;
    layoutItems();  // the polylines' pixel rows, for this size
    drawPolylines(context_, false);
}

void ParallelCoordinates::renderSelection() {
    selectionDirty_ = false;
    QElapsedTimer t;
    t.start();
    // Without brushes everything is selected: the colour layer is the plot.
    drawPolylines(selection_, true);
    selectionMs_ = double(t.nsecsElapsed()) / 1e6;
}

void ParallelCoordinates::paintEvent(QPaintEvent*) {
    ++paints_;
    // Drawn here, not at each mouse move: moves that arrive between two
    // frames cost one rasterisation.
    if (contextDirty_) renderContext();
    if (selectionDirty_) renderSelection();
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 31, 34));
    if (!model_) return;
    // The dimmed context only matters where brushes leave items out.
    if (!model_->brushes().empty()) p.drawImage(0, 0, context_);
    p.drawImage(0, 0, selection_);
    drawCurrent(p);
    drawAxes(p);
    drawBrushes(p);
}

void ParallelCoordinates::drawAxes(QPainter& p) const {
    const QFontMetrics fm = p.fontMetrics();
    p.setRenderHint(QPainter::Antialiasing, false);
    for (std::size_t a = 0; a < model_->axes().size(); ++a) {
        const ExplorerAxis& axis = model_->axes()[a];
        const double x = axisX(a);
        p.setPen(QPen(QColor(220, 222, 226), 1));
        p.drawLine(QPointF(x, yOf(1)), QPointF(x, yOf(0)));
        QFont bold = p.font();
        bold.setBold(true);
        p.setFont(bold);
        const QString name = QString::fromStdString(axis.name);
        p.drawText(QRectF(x - 80, 2, 160, fm.height()), Qt::AlignHCenter, name);
        p.setFont(QFont());
        p.setPen(QColor(190, 192, 198));
        // Labels may take most of the gap to the next axis.
        const std::size_t axes = model_->axes().size();
        const int room = axes > 1 ? std::max(kSide + 20, int((axisX(1) - axisX(0)) * 0.7)) : kSide + 20;
        auto label = [&](double unit, const QString& text) {
            // On a dark plate, readable over the polylines.
            const QString shown = fm.elidedText(text, Qt::ElideRight, room);
            const double w = fm.horizontalAdvance(shown) + 4;
            const bool last = a + 1 == axes && a > 0;  // its labels go left, inside the plot
            const QRectF r(last ? x - 4 - w : x + 4, yOf(unit) - fm.height() / 2.0, w, fm.height());
            p.fillRect(r, QColor(30, 31, 34, 190));
            p.drawText(r.adjusted(2, 0, 0, 0), Qt::AlignLeft | Qt::AlignVCenter, shown);
        };
        if (axis.numeric) {
            label(1, QString::fromStdString(shortestNumber(axis.maximum)));
            label(0, QString::fromStdString(shortestNumber(axis.minimum)));
        } else {
            // Every category while they fit, else every k-th.
            const std::size_t n = axis.categories.size();
            const double room = (yOf(0) - yOf(1)) / double(std::max<std::size_t>(1, n - 1));
            const std::size_t step = std::max<std::size_t>(1, std::size_t(std::ceil(fm.height() / std::max(1.0, room))));
            for (std::size_t k = 0; k < n; k += step)
                label(axis.toUnit(double(k)), QString::fromStdString(axis.categories[k]));
        }
    }
}

void ParallelCoordinates::drawBrushes(QPainter& p) const {
    p.setRenderHint(QPainter::Antialiasing, false);
    for (const auto& b : model_->brushes()) {
        const ExplorerAxis& axis = model_->axes()[b.axis];
        const double x = axisX(b.axis);
        const double top = yOf(std::clamp(axis.toUnit(b.high), 0.0, 1.0));
        const double bottom = yOf(std::clamp(axis.toUnit(b.low), 0.0, 1.0));
        // A brush around one value is still a visible mark.
        const double h = std::max(6.0, bottom - top + 2), mid = (top + bottom) / 2;
        const QRectF r(x - 7, mid - h / 2, 14, h);
        p.setPen(QPen(QColor(255, 176, 40), 1.5));
        p.setBrush(QColor(255, 176, 40, 70));
        p.drawRect(r);
    }
}

void ParallelCoordinates::drawCurrent(QPainter& p) const {
    if (!current_ || *current_ >= model_->size() || model_->axes().size() < 2) return;
    p.setRenderHint(QPainter::Antialiasing, true);
    QPolygonF line;
    for (std::size_t a = 0; a < model_->axes().size(); ++a) line << QPointF(axisX(a), itemY(a, *current_));
    p.setPen(QPen(QColor(20, 20, 20), 5));
    p.drawPolyline(line);
    p.setPen(QPen(QColor(255, 176, 40), 2.5));
    p.drawPolyline(line);
}

int ParallelCoordinates::axisNear(double x) const {
    if (!model_) return -1;
    for (std::size_t a = 0; a < model_->axes().size(); ++a)
        if (std::abs(x - axisX(a)) <= kReach) return int(a);
    return -1;
}

std::optional<std::size_t> ParallelCoordinates::polylineNear(QPointF at) const {
    const std::size_t axes = model_->axes().size();
    if (axes < 2) return std::nullopt;
    std::size_t a = 0;
    while (a + 2 < axes && at.x() > axisX(a + 1)) ++a;
    const double x0 = axisX(a), x1 = axisX(a + 1);
    const double t = std::clamp((at.x() - x0) / std::max(1.0, x1 - x0), 0.0, 1.0);
    std::optional<std::size_t> best;
    double bestDistance = 6;  // pixels
    for (std::size_t i = 0; i < model_->size(); ++i) {
        if (!model_->isSelected(i)) continue;
        const double d = std::abs(itemY(a, i) + t * (itemY(a + 1, i) - itemY(a, i)) - at.y());
        if (d < bestDistance) bestDistance = d, best = i;
    }
    return best;
}

void ParallelCoordinates::mousePressEvent(QMouseEvent* e) {
    if (!model_ || e->button() != Qt::LeftButton) return;
    pressAt_ = e->position();
    const int a = axisNear(e->position().x());
    if (a < 0) {
        if (const auto item = polylineNear(e->position())) {
            setCurrent(*item);
            emit picked(*item);
        }
        return;
    }
    const ExplorerAxis& axis = model_->axes()[std::size_t(a)];
    const double v = axis.fromUnit(unitAt(e->position().y()));
    const bool add = e->modifiers() & Qt::ShiftModifier;
    std::vector<Brush> brushes = model_->brushes();
    dragAxis_ = a;
    pressUnit_ = unitAt(e->position().y());
    for (std::size_t k = 0; k < brushes.size() && !add; ++k)
        if (brushes[k].axis == std::size_t(a) && v >= brushes[k].low && v <= brushes[k].high) {
            drag_ = Drag::Move;
            dragBrush_ = k;
            pressLow_ = axis.toUnit(brushes[k].low);
            pressHigh_ = axis.toUnit(brushes[k].high);
            return;
        }
    drag_ = Drag::Create;
    if (!add) std::erase_if(brushes, [a](const Brush& b) { return b.axis == std::size_t(a); });
    brushes.push_back({std::size_t(a), v, v});
    dragBrush_ = brushes.size() - 1;
    model_->setBrushes(std::move(brushes));
    selectionChanged();
    emit brushing();
}

void ParallelCoordinates::mouseMoveEvent(QMouseEvent* e) {
    if (drag_ == Drag::None || !model_) return;
    const ExplorerAxis& axis = model_->axes()[std::size_t(dragAxis_)];
    std::vector<Brush> brushes = model_->brushes();
    if (dragBrush_ >= brushes.size()) return;
    const double u = unitAt(e->position().y());
    Brush& b = brushes[dragBrush_];
    if (drag_ == Drag::Create) {
        b.low = axis.fromUnit(std::min(u, pressUnit_));
        b.high = axis.fromUnit(std::max(u, pressUnit_));
    } else {
        const double d = std::clamp(u - pressUnit_, -pressLow_, 1.0 - pressHigh_);
        b.low = axis.fromUnit(pressLow_ + d);
        b.high = axis.fromUnit(pressHigh_ + d);
    }
    model_->setBrushes(std::move(brushes));
    selectionChanged();
    emit brushing();
}

void ParallelCoordinates::mouseReleaseEvent(QMouseEvent* e) {
    if (drag_ == Drag::None || !model_) return;
    const bool click = std::abs(e->position().y() - pressAt_.y()) < 3;
    if (drag_ == Drag::Create && click) {
        // A click on an axis clears it (the brushes there went at the press).
        std::vector<Brush> brushes = model_->brushes();
        if (dragBrush_ < brushes.size()) brushes.erase(brushes.begin() + long(dragBrush_));
        model_->setBrushes(std::move(brushes));
        selectionChanged();
        emit brushing();
    }
    drag_ = Drag::None;
    emit brushed();
}

}  // namespace editor

