#pragma once
// The render view: a widget showing one image output over a checkerboard,
// with pan (drag), zoom (wheel, about the cursor), fit (double-click or F),
// 1:1 (1) and a pixel probe under the cursor. The image lives on the GPU
// (image_program.h); a frame is one textured quad, drawn into a native
// OpenGL window that fills the widget (render_surface.h says why it is not
// a QOpenGLWidget). The widget keeps the view's state and handles the
// window's input. A preview image (1/2^level of the full size) is drawn over
// the area of the full-size image, so the picture does not jump when the
// full frame lands. A layered buffer (darkroom/layers.h) is shown one layer,
// or its colour composite, at a time (layer_choice.h).
#include "display.h"

#include <darkroom/buffer.h>

#include <QImage>
#include <QWidget>

#include <memory>

class QPainter;
class QWindow;

namespace editor {

class ImageProgram;
class RenderSurface;

class RenderView : public QWidget {
    Q_OBJECT
public:
    explicit RenderView(QWidget* parent = nullptr);
    ~RenderView() override;
    // Null clears. `level`: the image is a preview at 1/2^level of the full
    // size. `tag` is handed back by presented() once the image is on screen.
    void setImage(darkroom::BufferPtr image, int level = 0, std::uint64_t tag = 0);
    // The buffer shown: for a layered image the chosen layer under the plain
    // channel names, or the composite; else the image as set.
    const darkroom::BufferPtr& image() const { return image_; }
    const darkroom::BufferPtr& sourceImage() const { return source_; }
    // The layer chooser's entries (layer_choice.h; empty for one layer) and
    // the current one. The choice is kept while new images offer it.
    const QStringList& layerChoices() const { return layerChoices_; }
    const QString& layerChoice() const { return layerChoice_; }
    void setLayerChoice(const QString& choice);
    int level() const { return level_; }
    QStringList modes() const { return modes_; }
    const QString& mode() const { return mode_; }
    void setMode(const QString& mode);
    void fit();
    double zoom() const { return zoom_; }  // screen pixels per full-resolution pixel
    QPointF offset() const { return offset_; }
    // Zoom and the widget position of the image's top-left corner.
    void setView(double zoom, QPointF offset);
    // Widget position -> pixel of the shown image (may be outside it).
    QPoint pixelAt(QPointF widgetPos) const;
    // Channel textures uploaded and mapping passes run so far (tests: pan
    // and zoom do neither).
    int uploads() const;
    int mappings() const;
    // The reduction the shown mapping was made at (image_program.h).
    int mappedLevel() const;
    // The OpenGL problem, when the view cannot draw.
    const QString& glError() const { return glError_; }
    // A message written over the view (an evaluation error naming the
    // node, "waiting for input"); empty clears. Errors are drawn in red.
    void setMessage(const QString& text, bool error);
    const QString& message() const { return message_; }
    bool messageIsError() const { return messageError_; }
    // The frame as drawn on screen, drawn again into an image of the view's
    // size (tests compare pixels; nothing is read from the window).
    QImage grabFramebuffer();
    // A frame is drawn at the next update request; renderNow draws it now.
    void requestFrame();
    void renderNow();
    // The native window the frames are drawn into (its input comes here).
    QWindow* surface() const;

signals:
    void modesChanged(const QStringList& modes, const QString& current);
    // The entries differ from the last image's (empty: one layer, no chooser).
    void layerChoicesChanged(const QStringList& choices, const QString& current);
    void probed(const QString& text);
    // The image set with `tag` reached the screen (the window's buffers swapped).
    void presented(std::uint64_t tag);
    void frameSwapped();  // any frame

protected:
    void resizeEvent(QResizeEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    QSizeF fullSize() const;  // the image's size in full-resolution pixels
    // After image_ changed: the modes it offers, the mapping, the probe.
    void showImage();
    void updateProbe(QPointF at);
    void initializeGL();
    // Draws the frame into `fbo` (bound), `pixels` in device pixels.
    void drawFrame(unsigned fbo, QSize pixels);
    void drawMessage(QPainter& p);

    RenderSurface* surface_;  // owned by its container, a child of this widget

    std::unique_ptr<ImageProgram> program_;
    darkroom::BufferPtr source_;  // as set
    darkroom::BufferPtr image_;   // as shown
    QStringList layerChoices_;
    QString layerChoice_;
    bool imageChanged_ = false;
    int level_ = 0;
    std::uint64_t tag_ = 0, drawnTag_ = 0, presentedTag_ = 0;
    bool drawnNew_ = false;
    QStringList modes_;
    QString mode_;
    DisplaySpec spec_;
    QString glError_;
    QString message_;
    bool messageError_ = false;
    double zoom_ = 1.0;     // screen pixels per full-resolution image pixel
    QPointF offset_;        // widget position of the image's top-left corner
    bool fitted_ = false;   // first image, or after fit(): follow resizes
    QPoint last_;
    QPointF hover_{-1, -1};
};

}  // namespace editor
