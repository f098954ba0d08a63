#include "polyline_raster.h"

#include "display.h"

#include <algorithm>
#include <cmath>
#include <thread>

namespace editor {

PolylineRaster::PolylineRaster(int w, int h, std::vector<int> axisX)
    : w_(std::max(1, w)), h_(std::max(1, h)), axisX_(std::move(axisX)), cells_(std::size_t(w_) * std::size_t(h_)) {}

void PolylineRaster::segment(int x0, float y0, int x1, float y1, float t, int lastColumn) {
    // Columns x0 .. lastColumn (the next gap owns x1 unless this is the last).
    const int dx = x1 - x0;
    const float dy = y1 - y0;
    if (dx <= 0 || x0 < 0 || lastColumn >= w_) return;
    Cell* cells = cells_.data();
    const std::size_t w = std::size_t(w_);
    auto plot = [&](int x, int y) {
        if (unsigned(y) >= unsigned(h_)) return;
        Cell& c = cells[std::size_t(y) * w + std::size_t(x)];
        ++c.count;
        c.sum += t;
    };
    if (std::abs(dy) <= float(dx)) {
        // One pixel per column; the row rounded (+0.5, rows are >= 0 here).
        const float slope = dy / float(dx);
        float y = y0 + 0.5f;
        const int end = std::min(x1, lastColumn);
        for (int x = x0; x <= end; ++x, y += slope) plot(x, int(y));
        return;
    }
    // Steep: one pixel per row, so the line has no gaps.
    const int ya = int(y0 + 0.5f), yb = int(y1 + 0.5f);
    const int step = yb > ya ? 1 : -1;
    const float inv = float(dx) / dy * float(step);  // columns per row step
    float x = float(x0) + (float(ya) - y0) * (float(dx) / dy) + 0.5f;
    for (int y = ya;; y += step, x += inv) {
        const int ix = int(x);
        if (ix <= lastColumn) plot(ix, y);
        if (y == yb) break;
    }
}

void PolylineRaster::rasterise(const std::function<void(std::size_t, const AddSegment&)>& each, int threads) {
    std::fill(cells_.begin(), cells_.end(), Cell{});
    if (axisX_.size() < 2) return;
    const std::size_t gaps = axisX_.size() - 1;
    auto run = [&](std::size_t gap) {
        const int x0 = axisX_[gap], x1 = axisX_[gap + 1];
        const int last = gap + 1 == gaps ? x1 : x1 - 1;
        each(gap, [&](float y0, float y1, float t) { segment(x0, y0, x1, y1, t, last); });
    };
    const std::size_t n = std::min<std::size_t>(gaps, std::size_t(std::max(1, threads)));
    if (n <= 1) {
        for (std::size_t g = 0; g < gaps; ++g) run(g);
        return;
    }
    std::vector<std::thread> pool;
    for (std::size_t k = 1; k < n; ++k)
        pool.emplace_back([&, k] {
            for (std::size_t g = k; g < gaps; g += n) run(g);
        });
    for (std::size_t g = 0; g < gaps; g += n) run(g);
    for (auto& t : pool) t.join();
}

QImage PolylineRaster::toImage(float scale, bool colour, QRgb grey, int maxAlpha) const {
    QImage out(w_, h_, QImage::Format_ARGB32_Premultiplied);
    // Opacity by count, looked up: counts above the table are opaque enough.
    std::vector<std::uint8_t> alpha(4096);
    for (std::size_t c = 0; c < alpha.size(); ++c)
        alpha[c] = std::uint8_t(std::lround(maxAlpha * (1.0 - std::exp(-double(c) / std::max(1e-3f, scale)))));
    const auto& table = falseColourTable();
    for (int y = 0; y < h_; ++y) {
        auto* row = reinterpret_cast<QRgb*>(out.scanLine(y));
        for (int x = 0; x < w_; ++x) {
            const Cell& cell = cells_[std::size_t(y) * std::size_t(w_) + std::size_t(x)];
            const std::uint32_t c = cell.count;
            if (c == 0) {
                row[x] = 0;
                continue;
            }
            const int a = alpha[std::min<std::size_t>(c, alpha.size() - 1)];
            int r = qRed(grey), g = qGreen(grey), b = qBlue(grey);
            if (colour) {
                const auto& e = table[std::size_t(std::clamp(int(cell.sum / float(c) * 255.0f + 0.5f), 0, 255))];
                r = e[0], g = e[1], b = e[2];
            }
            row[x] = qRgba(r * a / 255, g * a / 255, b * a / 255, a);  // premultiplied
        }
    }
    return out;
}

}  // namespace editor
