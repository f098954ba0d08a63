#pragma once
// Parallel coordinates of the explorer's items: one vertical axis per
// parameter column (numeric from minimum to maximum, text with its
// categories spread evenly), one polyline per item. The polylines are
// rasterised (polyline_raster.h) into two cached images: every item in grey
// (redrawn on resize) and the selected items in colour (redrawn when the
// selection changes); a paint composes them and draws the axes, brushes and
// the picked item with QPainter on top, so picking costs no polylines.
//
// Brushing: drag along an axis to select a range (replacing that axis'
// brushes), Shift+drag to add another range on it, drag inside a brush to
// move it, click on an axis to clear it. A click elsewhere picks the
// nearest selected polyline.
#include <QImage>
#include <QWidget>

#include <optional>
#include <vector>

namespace editor {

class ExplorerModel;

class ParallelCoordinates : public QWidget {
    Q_OBJECT
public:
    explicit ParallelCoordinates(QWidget* parent = nullptr);
    // Not owned; brushing changes its brushes.
    void setModel(ExplorerModel* model);
    // The brushes or the sort order changed elsewhere (a loaded state).
    void selectionChanged();
    void setCurrent(std::optional<std::size_t> item);

    // Geometry, for tests and the benchmark.
    double axisX(std::size_t axis) const;
    double yOf(double unit) const;  // unit 0 at the bottom of an axis, 1 at the top
    QPoint pointOf(std::size_t axis, double value) const;  // axis units (value or category position)
    int paints() const { return paints_; }
    double lastSelectionMs() const { return selectionMs_; }  // time to draw the selected polylines

signals:
    void brushing();  // the brushes changed during a drag
    void brushed();   // a brush gesture ended
    void picked(std::size_t item);

protected:
    void paintEvent(QPaintEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void mousePressEvent(QMouseEvent* e) override;
    void mouseMoveEvent(QMouseEvent* e) override;
    void mouseReleaseEvent(QMouseEvent* e) override;

private:
    void renderContext();
    void renderSelection();
    void drawPolylines(QImage& target, bool selectedOnly);
    void drawAxes(QPainter& p) const;
    void drawBrushes(QPainter& p) const;
    void drawCurrent(QPainter& p) const;
    int axisNear(double x) const;  // -1: none within reach
    double unitAt(double y) const;
    std::optional<std::size_t> polylineNear(QPointF at) const;
    double itemY(std::size_t axis, std::size_t item) const;
    void layoutItems();

    ExplorerModel* model_ = nullptr;
    QImage context_, selection_;
    bool contextDirty_ = true, selectionDirty_ = true;
    std::vector<std::vector<float>> ys_;  // per axis, per item: its pixel row
    std::optional<std::size_t> current_;
    int paints_ = 0;
    double selectionMs_ = 0;
    // The gesture in progress.
    enum class Drag { None, Create, Move } drag_ = Drag::None;
    int dragAxis_ = -1;
    std::size_t dragBrush_ = 0;
    double pressUnit_ = 0, pressLow_ = 0, pressHigh_ = 0;
    QPointF pressAt_;
};

}  // namespace editor
