#pragma once
// The render view's native OpenGL window, hosted in the view's widget with
// QWidget::createWindowContainer.
//
// Why not a QOpenGLWidget: a window holding one is composed by Qt through
// OpenGL at every repaint of any widget in it (the raster backing store is
// uploaded as a texture and the whole window drawn and swapped). On Mesa
// llvmpipe that is a software pass over all of a 1560 x 960 window, 30-60
// ms on the 2-core machine, paid by every frame of the graph, the explorer
// or the status bar. As a native child window the view swaps only its own
// area, and the rest of the window is flushed by the raster backing store,
// damaged region only.
//
// The window owns its context and draws when asked (update requests and
// exposure); the widget that owns it draws through the `paint` callback
// and receives its input: mouse, wheel and key events are sent to the
// owner unchanged (the container fills the owner, so positions agree), and
// drag-and-drop events to the owner's top-level widget, positions mapped.
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QWindow>

#include <functional>
#include <memory>

class QWidget;

namespace editor {

class RenderSurface : public QWindow {
    Q_OBJECT
public:
    // `initialize` runs once with the context current; `paint` draws a
    // frame into the framebuffer bound when it is called.
    RenderSurface(QWidget* owner, std::function<void()> initialize, std::function<void()> paint);
    ~RenderSurface() override;
    // Makes the context current on this window, or on an offscreen surface
    // before the window exists; creates the context and runs `initialize`
    // on first use. False when OpenGL is not available.
    bool makeCurrent();
    void doneCurrent();
    QOpenGLContext* context() const { return context_.get(); }
    // Draws and swaps now, when exposed.
    void renderNow();
    // The owner is going: no more callbacks, no more forwarded events.
    void detach();

signals:
    void frameSwapped();

protected:
    bool event(QEvent* e) override;
    void exposeEvent(QExposeEvent* e) override;

private:
    bool forwardDrag(QEvent* e);

    QWidget* owner_;
    std::function<void()> initialize_, paint_;
    std::unique_ptr<QOpenGLContext> context_;
    std::unique_ptr<QOffscreenSurface> offscreen_;  // current before the window is created
    bool initialized_ = false;
};

}  // namespace editor
