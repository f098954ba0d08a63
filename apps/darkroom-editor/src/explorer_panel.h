#pragma once
// The explorer of a Cinema database: parallel coordinates of its parameter
// columns beside a grid of the entries the brushes select, linked: brushing
// filters the grid, picking a polyline or a picture picks that entry (the
// window then shades it in the render view and moves the browser's
// sliders). A bar above says how many entries are selected, sorts the grid
// by any column, chooses what the grid shows (the raw product, or the
// pipeline's output for each entry) and copies the selection as a where-
// clause for `darkroom run --foreach ... --where`.
#include "explorer_model.h"
#include "explorer_state.h"
#include "thumbnail_sources.h"

#include <QWidget>

#include <memory>
#include <optional>

class QComboBox;
class QLabel;
class QToolButton;

namespace darkroom { class Registry; }

namespace editor {

class ImageGrid;
class ParallelCoordinates;
class ThumbnailCache;

class ExplorerPanel : public QWidget {
    Q_OBJECT
public:
    explicit ExplorerPanel(const darkroom::Registry& registry, QWidget* parent = nullptr);
    ~ExplorerPanel() override;

    // A database opened in the browser: its entries become the items.
    void setDatabase(const darkroom::CinemaDatabase& db, const std::vector<CinemaEntry>& entries);
    bool hasDatabase() const { return !database_.empty(); }
    const std::string& database() const { return database_; }
    // What "Pipeline output" evaluates; `graph` null: the pipeline cannot
    // shade an entry (no CinemaReader, nothing shown), the choice is off.
    void setPipeline(std::shared_ptr<const darkroom::Graph> graph, const PipelineThumbnails& spec);
    void setCurrent(std::optional<std::size_t> item);
    std::optional<std::size_t> current() const { return current_; }

    // The selection as saved with the pipeline, and back.
    ExplorerState state() const;
    // Problems (a column the database lacks) go to `problems`.
    void setState(const ExplorerState& s, std::vector<std::string>* problems = nullptr);
    bool showsPipeline() const { return pipelineMode_; }
    void setShowsPipeline(bool on);
    // The where-clause of the selection, checked against the database's own
    // query (what --where runs); "" without brushes.
    QString whereClause() const;
    void copyWhereClause();

    ExplorerModel& model() { return model_; }
    ParallelCoordinates* plot() const { return plot_; }
    ImageGrid* grid() const { return grid_; }
    ThumbnailCache* cache() const { return cache_; }
    QLabel* countLabel() const { return count_; }
    QComboBox* sortBox() const { return sort_; }
    QComboBox* showBox() const { return show_; }

signals:
    void picked(std::size_t item);
    void stateChanged();  // a brush gesture ended, the sort or what is shown changed
    void message(const QString& text);

private:
    void selectionChanged();
    void updateCount();
    void restartThumbnails();
    void onPicked(std::size_t item);

    const darkroom::Registry& registry_;
    std::string database_;
    std::optional<darkroom::CinemaDatabase> db_;  // a copy: the browser may open another
    std::vector<std::size_t> rows_;  // each item's CinemaReader `entry`
    ExplorerModel model_;
    std::optional<std::size_t> current_;
    bool pipelineMode_ = false;
    std::shared_ptr<const darkroom::Graph> pipeline_;
    PipelineThumbnails pipelineSpec_;
    std::string pipelineKey_;
    ThumbnailCache* cache_;
    ParallelCoordinates* plot_;
    ImageGrid* grid_;
    QLabel* count_;
    QComboBox* sort_;
    QToolButton* descending_;
    QComboBox* show_;
    bool updating_ = false;
};

}  // namespace editor
