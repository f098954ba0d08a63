#pragma once
// The render view: an OpenGL widget showing one image output over a
// checkerboard, with pan (drag), zoom (wheel, about the cursor), fit
// (double-click or F) and a pixel probe under the cursor.
#include <darkroom/buffer.h>

#include <QImage>
#include <QOpenGLWidget>

namespace editor {

class RenderView : public QOpenGLWidget {
    Q_OBJECT
public:
    explicit RenderView(QWidget* parent = nullptr);
    void setImage(darkroom::BufferPtr image);  // null clears
    const darkroom::BufferPtr& image() const { return image_; }
    QStringList modes() const { return modes_; }
    const QString& mode() const { return mode_; }
    void setMode(const QString& mode);
    const QImage& displayImage() const { return display_; }
    void fit();
    // Widget position -> image pixel (may be outside the image).
    QPoint pixelAt(QPointF widgetPos) const;

signals:
    void modesChanged(const QStringList& modes, const QString& current);
    void probed(const QString& text);

protected:
    void paintGL() override;
    void resizeGL(int w, int h) override;
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseDoubleClickEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;

private:
    darkroom::BufferPtr image_;
    QStringList modes_;
    QString mode_;
    QImage display_;
    double zoom_ = 1.0;     // screen pixels per image pixel
    QPointF offset_;        // widget position of the image's top-left corner
    bool fitted_ = false;   // first image, or after fit(): follow resizes
    QPoint last_;
};

}  // namespace editor
