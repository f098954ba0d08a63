#include "graph_view.h"

#include <QCursor>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QScrollBar>
#include <QWheelEvent>

#include <algorithm>
#include <cmath>

namespace editor {

GraphView::GraphView(QGraphicsScene* scene, QWidget* parent) : QGraphicsView(scene, parent) {
    setRenderHint(QPainter::Antialiasing);
    setDragMode(RubberBandDrag);
    setTransformationAnchor(AnchorUnderMouse);
    // Only what changed is repainted: during a value drag that is one widget
    // and the time badges, not every node's widgets.
    setViewportUpdateMode(SmartViewportUpdate);
    setAcceptDrops(false);  // files dropped here go to the main window
}

void GraphView::fitAll() {
    const QRectF r = scene()->itemsBoundingRect().adjusted(-30, -30, 30, 30);
    if (r.isEmpty()) return;
    const QSize vp = viewport()->size();
    const double s = std::clamp(std::min(vp.width() / r.width(), vp.height() / r.height()), kReadableZoom, 1.0);
    setTransform(QTransform::fromScale(s, s));
    // Per axis: centred when it fits, else from its start.
    const double w = vp.width() / s, h = vp.height() / s;
    const double cx = r.width() <= w ? r.center().x() : r.left() + w / 2;
    const double cy = r.height() <= h ? r.center().y() : r.top() + h / 2;
    centerOn(cx, cy);
}

bool GraphView::event(QEvent* e) {
    // Tab would move the keyboard focus; over the graph it opens the
    // quick-add menu, unless a value widget in a node is being typed in.
    if (e->type() == QEvent::KeyPress && static_cast<QKeyEvent*>(e)->key() == Qt::Key_Tab &&
        !(scene() && scene()->focusItem())) {
        QPoint at = hover_;
        if (!viewport()->rect().contains(at)) at = viewport()->mapFromGlobal(QCursor::pos());
        if (!viewport()->rect().contains(at)) at = viewport()->rect().center();
        emit quickAddRequested(at);
        return true;
    }
    return QGraphicsView::event(e);
}

void GraphView::wheelEvent(QWheelEvent* e) {
    const double f = std::pow(1.0015, e->angleDelta().y());
    const double s = transform().m11() * f;
    if (s < 0.1 || s > 4.0) return;
    scale(f, f);
    e->accept();
}

void GraphView::mousePressEvent(QMouseEvent* e) {
    if (e->button() == Qt::MiddleButton || (e->button() == Qt::LeftButton && (e->modifiers() & Qt::AltModifier))) {
        panning_ = true;
        last_ = e->position().toPoint();
        setCursor(Qt::ClosedHandCursor);
        e->accept();
        return;
    }
    QGraphicsView::mousePressEvent(e);
}

void GraphView::mouseMoveEvent(QMouseEvent* e) {
    hover_ = e->position().toPoint();
    if (panning_) {
        const QPoint d = e->position().toPoint() - last_;
        last_ = e->position().toPoint();
        horizontalScrollBar()->setValue(horizontalScrollBar()->value() - d.x());
        verticalScrollBar()->setValue(verticalScrollBar()->value() - d.y());
        e->accept();
        return;
    }
    QGraphicsView::mouseMoveEvent(e);
}

void GraphView::mouseReleaseEvent(QMouseEvent* e) {
    if (panning_) {
        panning_ = false;
        unsetCursor();
        e->accept();
        return;
    }
    QGraphicsView::mouseReleaseEvent(e);
}

}  // namespace editor
