#pragma once
// The explorer's image grid: the selected items in their sorted order, one
// thumbnail per cell. Virtualised: it lays out nothing per item and paints
// only the visible cells, asking the thumbnail cache for those (and the
// screen below, to scroll into) each time it paints; 10,000 items cost what
// the visible ones cost. A click (or the arrow keys) picks an item.
#include <QAbstractScrollArea>
#include <QRegion>
#include <QStringList>
#include <QTimer>

#include <optional>
#include <utility>
#include <vector>

namespace editor {

class ExplorerModel;
class ThumbnailCache;

class ImageGrid : public QAbstractScrollArea {
    Q_OBJECT
public:
    explicit ImageGrid(QWidget* parent = nullptr);
    // `labels[item]`: the entry's readable label (tooltips, captions).
    void setModel(const ExplorerModel* model, ThumbnailCache* cache, QStringList labels);
    // The selection or its order changed. `showCurrent`: scroll the current
    // item into view (a new order, a loaded selection), not while brushing.
    void modelChanged(bool showCurrent = false);
    void setCurrent(std::optional<std::size_t> item);  // highlighted; scrolled into view
    std::optional<std::size_t> current() const { return current_; }

    int columns() const;
    QSize cellSize() const;
    std::vector<std::size_t> visibleItems() const;
    QRect cellRect(std::size_t item) const;  // viewport coordinates; empty when not in the grid
    std::optional<std::size_t> itemAt(QPoint viewportPos) const;
    int paints() const { return paints_; }

signals:
    void picked(std::size_t item);

protected:
    void paintEvent(QPaintEvent* e) override;
    void resizeEvent(QResizeEvent* e) override;
    void scrollContentsBy(int dx, int dy) override;
    void mousePressEvent(QMouseEvent* e) override;
    void keyPressEvent(QKeyEvent* e) override;
    bool viewportEvent(QEvent* e) override;

private:
    void updateScrollRange();
    void ensureVisible(std::size_t position);
    int positionOf(std::size_t item) const;  // in the sorted selection; -1 when not selected
    QRect cellAt(int position) const;
    std::pair<std::size_t, std::size_t> visibleRange() const;  // positions [first, last)
    QString caption(std::size_t item) const;

    const ExplorerModel* model_ = nullptr;
    ThumbnailCache* cache_ = nullptr;
    QStringList labels_;
    std::optional<std::size_t> current_;
    int paints_ = 0;
    QTimer arrivals_;  // thumbnails that landed are painted together
    QRegion arrived_;
};

}  // namespace editor
