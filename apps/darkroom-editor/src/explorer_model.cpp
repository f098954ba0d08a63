#include "explorer_model.h"

#include <darkroom/data/cinema/composable.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <numeric>

namespace editor {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string quoteName(const std::string& name) {
    std::string out = "\"";
    for (char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
    return out + "\"";
}

std::string quoteText(const std::string& text) {
    std::string out = "'";
    for (char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
    return out + "'";
}

}  // namespace

std::string shortestNumber(double v) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

double ExplorerAxis::toUnit(double v) const {
    const double lo = numeric ? minimum : 0.0;
    const double hi = numeric ? maximum : double(categories.size()) - 1.0;
    return hi > lo ? (v - lo) / (hi - lo) : 0.5;
}

double ExplorerAxis::fromUnit(double t) const {
    const double lo = numeric ? minimum : 0.0;
    const double hi = numeric ? maximum : double(categories.size()) - 1.0;
    return hi > lo ? lo + t * (hi - lo) : lo;
}

ExplorerModel::ExplorerModel(const darkroom::CinemaDatabase& db, const std::vector<CinemaEntry>& entries) {
    const bool composable = darkroom::isComposableImageSet(db);
    for (const auto& e : entries) {
        rows_.push_back(e.row);
        allRows_.push_back({e.row});
    }
    if (composable) {
        // The same order as cinemaEntries(): images, then their layers.
        std::size_t i = 0;
        for (const auto& image : darkroom::composableImages(db))
            for (const auto& layer : image.layers) {
                if (i >= allRows_.size()) break;
                allRows_[i].clear();
                for (const auto& c : layer.channels) allRows_[i].push_back(c.row);
                ++i;
            }
    }
    for (std::size_t c : db.parameterColumns()) {
        const auto& col = db.columns()[c];
        // A composable set's CIS columns describe channels and layers, not
        // parameters (the browser leaves them out too).
        if (composable && col.name.rfind("CIS", 0) == 0) continue;
        ExplorerAxis a;
        a.column = c;
        a.name = col.name;
        a.numeric = col.numeric;
        std::vector<double> v(size(), kNaN);
        if (a.numeric) {
            a.minimum = std::isnan(col.minimum) ? 0.0 : col.minimum;
            a.maximum = std::isnan(col.maximum) ? 0.0 : col.maximum;
            for (std::size_t i = 0; i < size(); ++i) v[i] = db.number(rows_[i], c);
        } else {
            a.categories = col.distinct;
            for (std::size_t i = 0; i < size(); ++i) {
                const auto& cell = db.cell(rows_[i], c);
                const auto it = std::find(a.categories.begin(), a.categories.end(), cell);
                if (it == a.categories.end()) a.categories.push_back(cell);  // distinct leaves empty cells out
                v[i] = double(std::find(a.categories.begin(), a.categories.end(), cell) - a.categories.begin());
            }
        }
        std::vector<float> u(size());
        for (std::size_t i = 0; i < size(); ++i) u[i] = std::isnan(v[i]) ? NAN : float(a.toUnit(v[i]));
        axes_.push_back(std::move(a));
        values_.push_back(std::move(v));
        units_.push_back(std::move(u));
    }
    selected_.assign(size(), 1);
    select();
}

int ExplorerModel::axisIndex(const std::string& name) const {
    for (std::size_t a = 0; a < axes_.size(); ++a)
        if (axes_[a].name == name) return int(a);
    return -1;
}

QString ExplorerModel::text(std::size_t axis, std::size_t item) const {
    const double v = values_[axis][item];
    const ExplorerAxis& a = axes_[axis];
    if (std::isnan(v)) return QString();
    return a.numeric ? QString::fromStdString(shortestNumber(v)) : QString::fromStdString(a.categories[std::size_t(v)]);
}

void ExplorerModel::setBrushes(std::vector<Brush> brushes) {
    for (auto& b : brushes)
        if (b.low > b.high) std::swap(b.low, b.high);
    std::erase_if(brushes, [this](const Brush& b) { return b.axis >= axes_.size(); });
    if (brushes == brushes_) return;
    brushes_ = std::move(brushes);
    select();
}

bool ExplorerModel::inside(const Brush& b, double v) const {
    if (std::isnan(v)) return false;
    if (axes_[b.axis].numeric) return v >= b.low && v <= b.high;
    // Text: the categories whose position the brush covers.
    return v >= std::ceil(b.low - 1e-9) && v <= std::floor(b.high + 1e-9);
}

void ExplorerModel::select() {
    const std::size_t n = size();
    std::fill(selected_.begin(), selected_.end(), std::uint8_t(1));
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        std::vector<const Brush*> on;
        for (const auto& b : brushes_)
            if (b.axis == a) on.push_back(&b);
        if (on.empty()) continue;
        const auto& v = values_[a];
        for (std::size_t i = 0; i < n; ++i) {
            if (!selected_[i]) continue;
            bool any = false;
            for (const Brush* b : on) any = any || inside(*b, v[i]);
            selected_[i] = any;
        }
    }
    sort();
}

void ExplorerModel::setSort(int axis, bool descending) {
    if (axis >= int(axes_.size())) axis = -1;
    if (axis == sortAxis_ && descending == descending_) return;
    sortAxis_ = axis;
    descending_ = descending;
    sort();
}

void ExplorerModel::sort() {
    order_.clear();
    for (std::size_t i = 0; i < size(); ++i)
        if (selected_[i]) order_.push_back(std::uint32_t(i));
    if (sortAxis_ < 0) {
        if (descending_) std::reverse(order_.begin(), order_.end());
        return;
    }
    const auto& v = values_[std::size_t(sortAxis_)];
    const bool down = descending_;
    // Missing values last either way; equal values keep database order.
    std::stable_sort(order_.begin(), order_.end(), [&v, down](std::uint32_t a, std::uint32_t b) {
        const double x = v[a], y = v[b];
        if (std::isnan(x) || std::isnan(y)) return !std::isnan(x) && std::isnan(y);
        return down ? x > y : x < y;
    });
}

std::string ExplorerModel::axisTerm(std::size_t axis, bool midpoints) const {
    const ExplorerAxis& a = axes_[axis];
    const std::string name = quoteName(a.name);
    std::vector<std::string> alternatives;
    for (const auto& b : brushes_) {
        if (b.axis != axis) continue;
        if (!a.numeric) {
            std::string list;
            for (std::size_t k = 0; k < a.categories.size(); ++k)
                if (inside(b, double(k))) list += (list.empty() ? "" : ", ") + quoteText(a.categories[k]);
            if (!list.empty()) alternatives.push_back(name + " IN (" + list + ")");
            continue;
        }
        // The values the brush holds, and their neighbours outside it.
        double lo = INFINITY, hi = -INFINITY, below = -INFINITY, above = INFINITY;
        for (double v : values_[axis]) {
            if (std::isnan(v)) continue;
            if (inside(b, v)) lo = std::min(lo, v), hi = std::max(hi, v);
            else if (v < b.low) below = std::max(below, v);
            else above = std::min(above, v);
        }
        if (lo > hi) continue;  // an empty brush selects nothing
        if (midpoints) {
            if (std::isfinite(below)) lo = below + (lo - below) / 2;
            if (std::isfinite(above)) hi = hi + (above - hi) / 2;
        }
        alternatives.push_back(lo == hi && !midpoints ? name + " = " + shortestNumber(lo)
                                                      : name + " >= " + shortestNumber(lo) + " AND " + name +
                                                            " <= " + shortestNumber(hi));
    }
    if (alternatives.empty()) return "0";  // nothing on this axis: no row
    if (alternatives.size() == 1) return alternatives.front();
    std::string out;
    for (const auto& t : alternatives) out += (out.empty() ? "(" : " OR (") + t + ")";
    return "(" + out + ")";
}

std::string ExplorerModel::whereClause(bool midpoints) const {
    std::string out;
    for (std::size_t a = 0; a < axes_.size(); ++a) {
        if (std::none_of(brushes_.begin(), brushes_.end(), [a](const Brush& b) { return b.axis == a; })) continue;
        out += (out.empty() ? "" : " AND ") + axisTerm(a, midpoints);
    }
    return out;
}

std::vector<std::size_t> ExplorerModel::selectedRows() const {
    std::vector<std::size_t> rows;
    for (std::size_t i = 0; i < size(); ++i)
        if (selected_[i]) rows.insert(rows.end(), allRows_[i].begin(), allRows_[i].end());
    std::sort(rows.begin(), rows.end());
    return rows;
}

}  // namespace editor
