#include "render_view.h"

#include "image_program.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLFunctions>
#include <QPainter>
#include <QWheelEvent>

#include <cmath>

namespace editor {

RenderView::RenderView(QWidget* parent) : QOpenGLWidget(parent), program_(std::make_unique<ImageProgram>()) {
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 150);
    connect(this, &QOpenGLWidget::frameSwapped, this, [this] {
        if (!drawnNew_) return;
        drawnNew_ = false;
        presentedTag_ = drawnTag_;
        emit presented(presentedTag_);
    });
}

RenderView::~RenderView() {
    // Textures and the shader belong to this widget's context.
    makeCurrent();
    program_.reset();
    doneCurrent();
}

int RenderView::uploads() const { return program_->uploads(); }

int RenderView::mappings() const { return program_->mappings(); }

int RenderView::mappedLevel() const { return program_->mappedLevel(); }

QSizeF RenderView::fullSize() const {
    if (!image_) return {};
    const double f = std::ldexp(1.0, level_);
    return QSizeF(image_->width() * f, image_->height() * f);
}

void RenderView::setImage(darkroom::BufferPtr image, int level, std::uint64_t tag) {
    const QSizeF before = fullSize();
    image_ = std::move(image);
    level_ = image_ ? level : 0;
    tag_ = tag;
    imageChanged_ = true;
    // A preview's size is the full size rounded to 1/2^level: within one
    // preview pixel of the last full frame counts as the same picture.
    const QSizeF now = fullSize();
    const double slack = std::ldexp(1.0, level_);
    const bool sizeChanged = before.isEmpty() != now.isEmpty() || std::abs(before.width() - now.width()) > slack ||
                             std::abs(before.height() - now.height()) > slack;
    const QStringList modes = image_ ? displayModes(*image_) : QStringList();
    const bool newModes = modes != modes_;
    modes_ = modes;
    if (!modes_.contains(mode_)) mode_ = preferredMode(modes_);
    spec_ = image_ ? displaySpec(*image_, mode_) : DisplaySpec{};
    if (sizeChanged) fitted_ = true;
    if (fitted_) fit();
    if (newModes) emit modesChanged(modes_, mode_);
    if (hover_.x() >= 0) updateProbe(hover_);
    update();
}

void RenderView::setMode(const QString& mode) {
    if (mode == mode_ || !modes_.contains(mode)) return;
    mode_ = mode;
    spec_ = image_ ? displaySpec(*image_, mode_) : DisplaySpec{};
    update();
}

void RenderView::fit() {
    fitted_ = true;
    const QSizeF s = fullSize();
    if (s.isEmpty() || width() <= 0) return;
    zoom_ = std::min(width() / s.width(), height() / s.height());
    offset_ = QPointF((width() - s.width() * zoom_) / 2, (height() - s.height() * zoom_) / 2);
    update();
}

void RenderView::setView(double zoom, QPointF offset) {
    zoom_ = std::clamp(zoom, 0.02, 64.0);
    offset_ = offset;
    fitted_ = false;
    update();
}

QPoint RenderView::pixelAt(QPointF p) const {
    const QPointF q = (p - offset_) / (zoom_ * std::ldexp(1.0, level_));
    return QPoint(int(std::floor(q.x())), int(std::floor(q.y())));
}

void RenderView::initializeGL() {
    if (!program_->initialize(&glError_)) qWarning("darkroom-editor render view: %s", qPrintable(glError_));
}

void RenderView::resizeGL(int, int) {
    if (fitted_) fit();
}

void RenderView::paintGL() {
    auto* gl = context()->functions();
    gl->glClearColor(30 / 255.0f, 30 / 255.0f, 32 / 255.0f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    if (imageChanged_) {
        program_->setImage(image_);  // uploads happen below, for the channels the mode shows
        imageChanged_ = false;
    }
    const qreal dpr = devicePixelRatioF();
    if (image_ && spec_.kind != DisplaySpec::Kind::None && glError_.isEmpty()) {
        const QSizeF s = fullSize();
        const QRectF target(offset_ * dpr, s * zoom_ * dpr);
        program_->draw(spec_, target, QSize(int(width() * dpr), int(height() * dpr)), defaultFramebufferObject(),
                       level_ > 0);
    } else {
        QPainter p(this);
        p.setPen(Qt::lightGray);
        p.drawText(rect(), Qt::AlignCenter,
                   glError_.isEmpty() ? tr("Select a node with an image output") : tr("OpenGL: %1").arg(glError_));
    }
    if (!message_.isEmpty()) drawMessage();
    if (tag_ != drawnTag_) {
        drawnTag_ = tag_;
        drawnNew_ = true;  // announced when the window's buffers swap
    }
}

void RenderView::setMessage(const QString& text, bool error) {
    if (text == message_ && error == messageError_) return;
    message_ = text;
    messageError_ = error;
    update();
}

void RenderView::drawMessage() {
    // A banner along the top, over the picture (the last good frame stays
    // visible below it): the user sees what failed where they are looking.
    QPainter p(this);
    p.setRenderHint(QPainter::Antialiasing);
    const QRect box = rect().adjusted(8, 8, -8, -8);
    const QRect textRect = p.fontMetrics().boundingRect(box.adjusted(10, 6, -10, -6), Qt::TextWordWrap, message_);
    const QRect banner(box.left(), box.top(), box.width(), std::min(box.height(), textRect.height() + 14));
    p.setPen(Qt::NoPen);
    p.setBrush(messageError_ ? QColor(170, 28, 28, 235) : QColor(70, 72, 80, 230));
    p.drawRoundedRect(banner, 5, 5);
    p.setPen(Qt::white);
    p.drawText(banner.adjusted(10, 7, -10, -7), Qt::TextWordWrap | Qt::AlignLeft | Qt::AlignTop, message_);
}

void RenderView::updateProbe(QPointF at) {
    if (!image_) return;
    const QPoint px = pixelAt(at);
    QString text = probeText(*image_, px.x(), px.y());
    if (!text.isEmpty() && level_ > 0) text = tr("preview 1/%1: ").arg(1 << level_) + text;
    emit probed(text);
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
    hover_ = e->position();
    updateProbe(hover_);
}

void RenderView::mouseDoubleClickEvent(QMouseEvent*) { fit(); }

void RenderView::keyPressEvent(QKeyEvent* e) {
    if (e->key() == Qt::Key_F) fit();
    else if (e->key() == Qt::Key_1) {  // 1:1, centred
        const QSizeF s = fullSize();
        zoom_ = 1.0;
        offset_ = QPointF((width() - s.width()) / 2.0, (height() - s.height()) / 2.0);
        fitted_ = false;
        update();
    } else QOpenGLWidget::keyPressEvent(e);
}

}  // namespace editor
