#include "render_surface.h"

#include <QCoreApplication>
#include <QDropEvent>
#include <QExposeEvent>
#include <QOpenGLFunctions>
#include <QWidget>

namespace editor {

RenderSurface::RenderSurface(QWidget* owner, std::function<void()> initialize, std::function<void()> paint)
    : owner_(owner), initialize_(std::move(initialize)), paint_(std::move(paint)) {
    setSurfaceType(QSurface::OpenGLSurface);
    setFormat(QSurfaceFormat::defaultFormat());  // what a QOpenGLWidget asks for
}

RenderSurface::~RenderSurface() = default;  // the context goes before the offscreen surface

void RenderSurface::detach() {
    owner_ = nullptr;
    initialize_ = nullptr;
    paint_ = nullptr;
}

bool RenderSurface::makeCurrent() {
    if (!context_) {
        auto c = std::make_unique<QOpenGLContext>();
        c->setFormat(requestedFormat());
        if (!c->create()) return false;
        context_ = std::move(c);
    }
    bool ok = false;
    if (handle()) {
        ok = context_->makeCurrent(this);
    } else {
        if (!offscreen_) {
            offscreen_ = std::make_unique<QOffscreenSurface>();
            offscreen_->setFormat(context_->format());
            offscreen_->create();
        }
        ok = context_->makeCurrent(offscreen_.get());
    }
    if (ok && !initialized_ && initialize_) {
        initialized_ = true;
        initialize_();
    }
    return ok;
}

void RenderSurface::doneCurrent() {
    if (context_) context_->doneCurrent();
}

void RenderSurface::renderNow() {
    if (!isExposed() || !paint_ || !makeCurrent()) return;
    context_->functions()->glBindFramebuffer(GL_FRAMEBUFFER, context_->defaultFramebufferObject());
    paint_();
    context_->swapBuffers(this);
    emit frameSwapped();
}

void RenderSurface::exposeEvent(QExposeEvent*) {
    if (isExposed()) renderNow();
}

bool RenderSurface::event(QEvent* e) {
    switch (e->type()) {
    case QEvent::UpdateRequest:
        renderNow();
        return true;
    case QEvent::Resize:
        requestUpdate();
        break;
    case QEvent::MouseButtonPress:
    case QEvent::MouseButtonRelease:
    case QEvent::MouseButtonDblClick:
    case QEvent::MouseMove:
    case QEvent::Wheel:
    case QEvent::KeyPress:
    case QEvent::KeyRelease:
        if (owner_) return QCoreApplication::sendEvent(owner_, e);
        break;
    case QEvent::DragEnter:
    case QEvent::DragMove:
    case QEvent::DragLeave:
    case QEvent::Drop:
        if (owner_) return forwardDrag(e);
        break;
    default:
        break;
    }
    return QWindow::event(e);
}

// Files dropped on the view open as if dropped anywhere else on the window.
bool RenderSurface::forwardDrag(QEvent* e) {
    QWidget* top = owner_->window();
    if (e->type() == QEvent::DragLeave) {
        QDragLeaveEvent leave;
        return QCoreApplication::sendEvent(top, &leave);
    }
    auto* d = static_cast<QDropEvent*>(e);
    const QPoint at = owner_->mapTo(top, d->position().toPoint());
    std::unique_ptr<QDropEvent> f;
    if (e->type() == QEvent::DragEnter)
        f = std::make_unique<QDragEnterEvent>(at, d->possibleActions(), d->mimeData(), d->buttons(), d->modifiers());
    else if (e->type() == QEvent::DragMove)
        f = std::make_unique<QDragMoveEvent>(at, d->possibleActions(), d->mimeData(), d->buttons(), d->modifiers());
    else
        f = std::make_unique<QDropEvent>(QPointF(at), d->possibleActions(), d->mimeData(), d->buttons(), d->modifiers());
    f->setDropAction(d->dropAction());
    f->setAccepted(d->isAccepted());
    const bool handled = QCoreApplication::sendEvent(top, f.get());
    d->setDropAction(f->dropAction());
    d->setAccepted(f->isAccepted());
    return handled;
}

}  // namespace editor
