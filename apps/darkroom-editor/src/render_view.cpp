#include "render_view.h"

#include "display.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

namespace editor {

RenderView::RenderView(QWidget* parent) : QOpenGLWidget(parent) {
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 150);
}

void RenderView::setImage(darkroom::BufferPtr image) {
    const bool sizeChanged = !image_ || !image || image_->width() != image->width() ||
                             image_->height() != image->height();
    image_ = std::move(image);
    modes_ = image_ ? displayModes(*image_) : QStringList();
    if (!modes_.contains(mode_)) mode_ = modes_.isEmpty() ? QString() : modes_.front();
    display_ = image_ ? renderDisplay(*image_, mode_) : QImage();
    if (sizeChanged) fitted_ = true;
    if (fitted_) fit();
    emit modesChanged(modes_, mode_);
    update();
}

void RenderView::setMode(const QString& mode) {
    if (mode == mode_ || !modes_.contains(mode)) return;
    mode_ = mode;
    display_ = image_ ? renderDisplay(*image_, mode_) : QImage();
    update();
}

void RenderView::fit() {
    fitted_ = true;
    if (display_.isNull() || width() <= 0) return;
    zoom_ = std::min(double(width()) / display_.width(), double(height()) / display_.height());
    offset_ = QPointF((width() - display_.width() * zoom_) / 2, (height() - display_.height() * zoom_) / 2);
    update();
}

QPoint RenderView::pixelAt(QPointF p) const {
    const QPointF q = (p - offset_) / zoom_;
    return QPoint(int(std::floor(q.x())), int(std::floor(q.y())));
}

void RenderView::resizeGL(int, int) {
    if (fitted_) fit();
}

void RenderView::paintGL() {
    // QPainter on a QOpenGLWidget draws through OpenGL; images up to a few
    // megapixels are uploaded as textures quickly enough for live editing.
    QPainter p(this);
    p.fillRect(rect(), QColor(30, 30, 32));
    if (display_.isNull()) {
        p.setPen(Qt::lightGray);
        p.drawText(rect(), Qt::AlignCenter, tr("Select a node with an image output"));
        return;
    }
    const QRectF target(offset_, QSizeF(display_.width() * zoom_, display_.height() * zoom_));
    // The checkerboard shows through transparent pixels (alpha, background).
    QPixmap checker(16, 16);
    checker.fill(QColor(150, 150, 150));
    QPainter c(&checker);
    c.fillRect(0, 0, 8, 8, QColor(100, 100, 100));
    c.fillRect(8, 8, 8, 8, QColor(100, 100, 100));
    c.end();
    p.fillRect(target, QBrush(checker));
    // Nearest-neighbour when magnified, so single pixels can be probed.
    p.setRenderHint(QPainter::SmoothPixmapTransform, zoom_ < 1.0);
    p.drawImage(target, display_);
}

void RenderView::wheelEvent(QWheelEvent* e) {
    const double f = std::pow(1.0015, e->angleDelta().y());
    const double z = std::clamp(zoom_ * f, 0.02, 64.0);
    const QPointF at = e->position();
    offset_ = at - (at - offset_) * (z / zoom_);
    zoom_ = z;
    fitted_ = false;
    update();
}

void RenderView::mousePressEvent(QMouseEvent* e) { last_ = e->position().toPoint(); }

void RenderView::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & (Qt::LeftButton | Qt::MiddleButton)) {
        offset_ += e->position().toPoint() - last_;
        last_ = e->position().toPoint();
        fitted_ = false;
        update();
    }
    if (image_) {
        const QPoint px = pixelAt(e->position());
        emit probed(probeText(*image_, px.x(), px.y()));
    }
}

void RenderView::mouseDoubleClickEvent(QMouseEvent*) { fit(); }

void RenderView::keyPressEvent(QKeyEvent* e) {
    if (e->key() == Qt::Key_F) fit();
    else if (e->key() == Qt::Key_1) {  // 1:1, centred
        zoom_ = 1.0;
        offset_ = QPointF((width() - display_.width()) / 2.0, (height() - display_.height()) / 2.0);
        fitted_ = false;
        update();
    } else QOpenGLWidget::keyPressEvent(e);
}

}  // namespace editor
