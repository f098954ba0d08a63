#include "graph_view.h"

#include <QMouseEvent>
#include <cmath>
#include <QScrollBar>
#include <QWheelEvent>

namespace editor {

GraphView::GraphView(QGraphicsScene* scene, QWidget* parent) : QGraphicsView(scene, parent) {
    setRenderHint(QPainter::Antialiasing);
    setDragMode(RubberBandDrag);
    setTransformationAnchor(AnchorUnderMouse);
    setViewportUpdateMode(FullViewportUpdate);
    setAcceptDrops(false);  // files dropped here go to the main window
}

void GraphView::fitAll() {
    const QRectF r = scene()->itemsBoundingRect().adjusted(-30, -30, 30, 30);
    if (r.isEmpty()) return;
    fitInView(r, Qt::KeepAspectRatio);
    // Never blow small graphs up past 1:1; widgets stay legible.
    if (transform().m11() > 1.0) setTransform(QTransform());
    centerOn(r.center());
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
