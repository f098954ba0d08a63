#pragma once
// The parallel coordinates' polylines, rasterised by hand: QPainter's line
// drawing with alpha took 190-520 ms for 5,000 polylines on the 2-core
// machine (bench_explorer), far over the 50 ms a brush move may take.
//
// Each segment adds, to every pixel it crosses (one per column, or per row
// when steep), one to a count and its colour value t in [0, 1] to a sum.
// The image is then made per pixel: colour from the mean t (viridis, or
// grey), opacity from the count, 1 - exp(-count / scale), so one line of a
// hundred is clearly visible and one of ten thousand faint, as dense
// areas are. The result does not depend on the order of the lines.
// Segments between two neighbouring axes touch only the columns between
// them, so the gaps are rasterised in parallel without sharing a pixel.
#include <QImage>

#include <cstdint>
#include <functional>
#include <vector>

namespace editor {

class PolylineRaster {
public:
    // Axes at columns `axisX` (ascending) of a w x h image.
    PolylineRaster(int w, int h, std::vector<int> axisX);
    int width() const { return w_; }
    int height() const { return h_; }

    // Rasterises polylines in parallel, one gap between axes per task.
    // `each(gap, add)` must call add(y0, y1, t) for every polyline's segment
    // in that gap (from axis `gap` to axis `gap + 1`).
    using AddSegment = std::function<void(float y0, float y1, float t)>;
    void rasterise(const std::function<void(std::size_t gap, const AddSegment& add)>& each, int threads);

    // The image; `scale`: the count at which a pixel is 63 % opaque.
    // `colour`: viridis by the mean t, else `grey`.
    QImage toImage(float scale, bool colour, QRgb grey, int maxAlpha) const;

private:
    void segment(int x0, float y0, int x1, float y1, float t, int lastColumn);
    int w_, h_;
    std::vector<int> axisX_;
    struct Cell {
        std::uint32_t count = 0;  // lines crossing the pixel
        float sum = 0;            // of their colour values
    };
    std::vector<Cell> cells_;
};

}  // namespace editor
