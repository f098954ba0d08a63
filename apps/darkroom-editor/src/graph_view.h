#pragma once
// The view on the graph scene: wheel zoom about the cursor, middle-button
// (or Alt+left) pan, rubber-band selection on the background.
#include <QGraphicsView>

namespace editor {

class GraphView : public QGraphicsView {
    Q_OBJECT
public:
    explicit GraphView(QGraphicsScene* scene, QWidget* parent = nullptr);
    void fitAll();

protected:
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;

private:
    bool panning_ = false;
    QPoint last_;
};

}  // namespace editor
