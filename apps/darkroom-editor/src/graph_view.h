#pragma once
// The view on the graph scene: wheel zoom about the cursor, middle-button
// (or Alt+left) pan, rubber-band selection on the background, Tab for the
// quick-add menu at the cursor.
#include <QGraphicsView>

namespace editor {

class GraphView : public QGraphicsView {
    Q_OBJECT
public:
    // Below this scale node titles and value widgets are hard to read (the
    // default 9-point font falls under ~10 pixels): fitting never goes lower.
    static constexpr double kReadableZoom = 0.8;

    explicit GraphView(QGraphicsScene* scene, QWidget* parent = nullptr);
    // Shows the whole graph, between the readable zoom and 1:1. A graph too
    // large for that shows its beginning (sources at the left, top).
    void fitAll();
    double zoom() const { return transform().m11(); }

signals:
    // Tab over the background: `at` in viewport coordinates.
    void quickAddRequested(QPoint at);

protected:
    bool event(QEvent* e) override;
    void wheelEvent(QWheelEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;

private:
    bool panning_ = false;
    QPoint last_;
    QPoint hover_{-1, -1};  // last mouse position over the viewport
};

}  // namespace editor
