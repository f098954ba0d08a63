#include "render_view.h"

#include "image_program.h"
#include "layer_choice.h"
#include "render_surface.h"

#include <QKeyEvent>
#include <QMouseEvent>
#include <QOpenGLFramebufferObject>
#include <QOpenGLFunctions>
#include <QOpenGLPaintDevice>
#include <QPainter>
#include <QVBoxLayout>
#include <QWheelEvent>

#include <cmath>

namespace editor {

RenderView::RenderView(QWidget* parent) : QWidget(parent), program_(std::make_unique<ImageProgram>()) {
    setMouseTracking(true);
    setFocusPolicy(Qt::StrongFocus);
    setMinimumSize(200, 150);
    surface_ = new RenderSurface(this, [this] { initializeGL(); }, [this] {
        drawFrame(surface_->context()->defaultFramebufferObject(), surface_->size() * surface_->devicePixelRatio());
        if (tag_ != drawnTag_) {
            drawnTag_ = tag_;
            drawnNew_ = true;  // announced when the window's buffers swap
        }
    });
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(QWidget::createWindowContainer(surface_, this));
    connect(surface_, &RenderSurface::frameSwapped, this, [this] {
        emit frameSwapped();
        if (!drawnNew_) return;
        drawnNew_ = false;
        presentedTag_ = drawnTag_;
        emit presented(presentedTag_);
    });
}

RenderView::~RenderView() {
    // Textures and the shader belong to the window's context.
    surface_->detach();
    if (surface_->context() && surface_->makeCurrent()) {
        program_.reset();
        surface_->doneCurrent();
    }
}

void RenderView::requestFrame() { surface_->requestUpdate(); }

void RenderView::renderNow() { surface_->renderNow(); }

QWindow* RenderView::surface() const { return surface_; }

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
    source_ = std::move(image);
    level_ = source_ ? level : 0;
    tag_ = tag;
    // An ordinary buffer (one layer) has no choices and is shown as it is:
    // no view is built for it.
    QStringList choices = source_ ? editor::layerChoices(*source_) : QStringList();
    const bool newChoices = choices != layerChoices_;
    layerChoices_ = std::move(choices);
    if (!layerChoices_.contains(layerChoice_)) layerChoice_ = preferredLayerChoice(layerChoices_);
    image_ = layerChoices_.isEmpty() ? source_ : chooseLayer(source_, layerChoice_);
    // A preview's size is the full size rounded to 1/2^level: within one
    // preview pixel of the last full frame counts as the same picture.
    const QSizeF now = fullSize();
    const double slack = std::ldexp(1.0, level_);
    const bool sizeChanged = before.isEmpty() != now.isEmpty() || std::abs(before.width() - now.width()) > slack ||
                             std::abs(before.height() - now.height()) > slack;
    if (sizeChanged) fitted_ = true;
    if (fitted_) fit();
    if (newChoices) emit layerChoicesChanged(layerChoices_, layerChoice_);
    showImage();
}

void RenderView::setLayerChoice(const QString& choice) {
    if (choice == layerChoice_ || !layerChoices_.contains(choice)) return;
    layerChoice_ = choice;
    image_ = chooseLayer(source_, layerChoice_);
    showImage();
}

void RenderView::showImage() {
    imageChanged_ = true;
    const QStringList modes = image_ ? displayModes(*image_) : QStringList();
    const bool newModes = modes != modes_;
    modes_ = modes;
    if (!modes_.contains(mode_)) mode_ = preferredMode(modes_);
    spec_ = image_ ? displaySpec(*image_, mode_) : DisplaySpec{};
    if (newModes) emit modesChanged(modes_, mode_);
    if (hover_.x() >= 0) updateProbe(hover_);
    requestFrame();
}

void RenderView::setMode(const QString& mode) {
    if (mode == mode_ || !modes_.contains(mode)) return;
    mode_ = mode;
    spec_ = image_ ? displaySpec(*image_, mode_) : DisplaySpec{};
    requestFrame();
}

void RenderView::fit() {
    fitted_ = true;
    const QSizeF s = fullSize();
    if (s.isEmpty() || width() <= 0) return;
    zoom_ = std::min(width() / s.width(), height() / s.height());
    offset_ = QPointF((width() - s.width() * zoom_) / 2, (height() - s.height() * zoom_) / 2);
    requestFrame();
}

void RenderView::setView(double zoom, QPointF offset) {
    zoom_ = std::clamp(zoom, 0.02, 64.0);
    offset_ = offset;
    fitted_ = false;
    requestFrame();
}

QPoint RenderView::pixelAt(QPointF p) const {
    const QPointF q = (p - offset_) / (zoom_ * std::ldexp(1.0, level_));
    return QPoint(int(std::floor(q.x())), int(std::floor(q.y())));
}

void RenderView::initializeGL() {
    if (!program_->initialize(&glError_)) qWarning("darkroom-editor render view: %s", qPrintable(glError_));
}

void RenderView::resizeEvent(QResizeEvent* e) {
    QWidget::resizeEvent(e);
    if (fitted_) fit();
}

void RenderView::drawFrame(unsigned fbo, QSize pixels) {
    auto* gl = QOpenGLContext::currentContext()->functions();
    gl->glViewport(0, 0, pixels.width(), pixels.height());
    gl->glClearColor(30 / 255.0f, 30 / 255.0f, 32 / 255.0f, 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT);
    if (imageChanged_) {
        program_->setImage(image_);  // uploads happen below, for the channels the mode shows
        imageChanged_ = false;
    }
    const qreal dpr = devicePixelRatioF();
    const bool drawsImage = image_ && spec_.kind != DisplaySpec::Kind::None && glError_.isEmpty();
    if (drawsImage) program_->draw(spec_, QRectF(offset_ * dpr, fullSize() * zoom_ * dpr), pixels, fbo, level_ > 0);
    if (drawsImage && message_.isEmpty()) return;
    // Text over the frame with Qt's OpenGL paint engine, into the same framebuffer.
    QOpenGLPaintDevice device(pixels);
    device.setDevicePixelRatio(dpr);
    QPainter p(&device);
    if (!drawsImage) {
        p.setPen(Qt::lightGray);
        p.drawText(rect(), Qt::AlignCenter,
                   glError_.isEmpty() ? tr("Select a node with an image output") : tr("OpenGL: %1").arg(glError_));
    }
    if (!message_.isEmpty()) drawMessage(p);
}

QImage RenderView::grabFramebuffer() {
    if (!surface_->makeCurrent()) return {};
    const QSize pixels = size() * devicePixelRatioF();
    // A stencil buffer for the paint engine's clipping, as QOpenGLWidget has.
    QOpenGLFramebufferObject fbo(pixels, QOpenGLFramebufferObject::CombinedDepthStencil);
    fbo.bind();
    drawFrame(fbo.handle(), pixels);
    QImage image = fbo.toImage();
    fbo.release();
    return image;
}

void RenderView::setMessage(const QString& text, bool error) {
    if (text == message_ && error == messageError_) return;
    message_ = text;
    messageError_ = error;
    requestFrame();
}

void RenderView::drawMessage(QPainter& p) {
    // A banner along the top, over the picture (the last good frame stays
    // visible below it): the user sees what failed where they are looking.
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
    requestFrame();
}

void RenderView::mousePressEvent(QMouseEvent* e) { last_ = e->position().toPoint(); }

void RenderView::mouseMoveEvent(QMouseEvent* e) {
    if (e->buttons() & (Qt::LeftButton | Qt::MiddleButton)) {
        offset_ += e->position().toPoint() - last_;
        last_ = e->position().toPoint();
        fitted_ = false;
        requestFrame();
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
        requestFrame();
    } else QWidget::keyPressEvent(e);
}

}  // namespace editor
