#pragma once
// The explorer's table, without widgets: one item per Cinema entry (a
// data.csv row, or a layer of a composable image set, as the browser lists
// them), one axis per parameter column; brushes on the axes, the selection
// they make, sorted by any column; the selection as an SQL where-clause.
//
// Brushes on one axis are alternatives (OR), axes combine (AND): an item is
// selected when, on every brushed axis, its value lies in one of that axis'
// brushes. Numeric brushes are ranges of values; text brushes ranges of
// category positions (categories in order of first appearance). A missing
// value (an empty or NaN cell) is never inside a brush, as SQL's NULL.
#include "cinema_entries.h"

#include <darkroom/data/cinema/database.h>

#include <cstdint>
#include <string>
#include <vector>

namespace editor {

struct ExplorerAxis {
    std::size_t column = 0;  // in the database
    std::string name;
    bool numeric = false;
    double minimum = 0, maximum = 0;      // numeric: range of the finite values
    std::vector<std::string> categories;  // text: distinct values, in order of first appearance
    // Axis units (the value, or the category position) -> [0, 1] on the
    // axis, 0 at the bottom; a single value sits in the middle.
    double toUnit(double v) const;
    double fromUnit(double t) const;
};

struct Brush {
    std::size_t axis = 0;
    double low = 0, high = 0;  // axis units, low <= high
    bool operator==(const Brush&) const = default;
};

class ExplorerModel {
public:
    ExplorerModel() = default;
    ExplorerModel(const darkroom::CinemaDatabase& db, const std::vector<CinemaEntry>& entries);

    std::size_t size() const { return rows_.size(); }
    std::size_t row(std::size_t item) const { return rows_[item]; }  // its (first) data.csv row
    const std::vector<ExplorerAxis>& axes() const { return axes_; }
    int axisIndex(const std::string& name) const;  // -1 when absent
    // Axis units: the number, or the category position; NaN when missing.
    double value(std::size_t axis, std::size_t item) const { return values_[axis][item]; }
    // [0, 1] on the axis (NaN when missing), as the plot draws it.
    float unit(std::size_t axis, std::size_t item) const { return units_[axis][item]; }
    // The cell as a person reads it ("0.25", "a").
    QString text(std::size_t axis, std::size_t item) const;

    const std::vector<Brush>& brushes() const { return brushes_; }
    void setBrushes(std::vector<Brush> brushes);
    bool isSelected(std::size_t item) const { return selected_[item] != 0; }
    std::size_t selectedCount() const { return order_.size(); }
    // The selected items, sorted (stable: database order among equals).
    const std::vector<std::uint32_t>& order() const { return order_; }

    void setSort(int axis, bool descending);  // axis -1: database order
    int sortAxis() const { return sortAxis_; }
    bool descending() const { return descending_; }

    // The selection as an SQL WHERE expression for CinemaDatabase::query
    // (`darkroom run --foreach ... --where`): names in double quotes, text
    // in single quotes, numbers in shortest exact form. Empty without
    // brushes (every row). A numeric brush becomes the range of the values
    // it holds, so the clause selects the same rows whatever the brush's
    // screen-rounded ends. `midpoints`: ends halfway to the neighbouring
    // values instead (immune to how SQLite parses a decimal).
    std::string whereClause(bool midpoints = false) const;
    // The data.csv rows of the selected items, ascending (a composable
    // image set's layer is all its channel rows).
    std::vector<std::size_t> selectedRows() const;

private:
    void select();
    void sort();
    bool inside(const Brush& b, double v) const;
    std::string axisTerm(std::size_t axis, bool midpoints) const;

    std::vector<std::size_t> rows_;                  // per item
    std::vector<std::vector<std::size_t>> allRows_;  // per item: every data.csv row it stands for
    std::vector<ExplorerAxis> axes_;
    std::vector<std::vector<double>> values_;  // per axis, per item
    std::vector<std::vector<float>> units_;    // per axis, per item
    std::vector<Brush> brushes_;
    std::vector<std::uint8_t> selected_;
    std::vector<std::uint32_t> order_;
    int sortAxis_ = -1;
    bool descending_ = false;
};

// Shortest text that reads back as exactly `v` ("0.25", "1e-07").
std::string shortestNumber(double v);

}  // namespace editor
