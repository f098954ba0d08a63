#pragma once
// The Cinema browser: open a .cdb, choose an entry with one slider (numeric)
// or combo (text) per parameter column, or by clicking its thumbnail.
// Entries and thumbnails come from the pipeline's own CinemaReader
// (cinema_entries.h). Thumbnails are made on a pool thread, one at a time,
// and arrive as they are ready; opening another database drops the rest.
#include "cinema_entries.h"

#include <darkroom/data/cinema/database.h>

#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>

class QLabel;
class QListWidget;
class QFormLayout;

namespace darkroom { class Registry; }

namespace editor {

class CinemaPanel : public QWidget {
    Q_OBJECT
public:
    explicit CinemaPanel(const darkroom::Registry& registry, QWidget* parent = nullptr);
    ~CinemaPanel() override;
    // The entry to choose first: the one holding row `selectRow` (CinemaReader's
    // `entry`, as a loaded pipeline has it), else the first `selectParameters`
    // (its `parameters`) selects, else the first entry.
    bool open(const QString& path, QString* error, std::int64_t selectRow = -1, const QString& selectParameters = {});
    const darkroom::CinemaDatabase* database() const { return db_ ? &*db_ : nullptr; }
    const std::vector<CinemaEntry>& entries() const { return entries_; }
    std::size_t currentEntry() const { return entry_; }
    void selectEntry(std::size_t entry);  // moves the controls and emits entryChosen
    // One item per entry; its data(Qt::UserRole) turns true when the
    // thumbnail replaced the grey stand-in.
    QListWidget* thumbnails() const { return list_; }
    // Controls per parameter column (a QSlider or a QComboBox), for tests.
    QWidget* control(const QString& column) const;
    // Entries whose thumbnail failed, with CinemaReader's message (tooltips).
    int thumbnailFailures() const { return failures_; }

signals:
    // The database folder and the entry's first row, as CinemaReader's `entry`.
    void entryChosen(const QString& database, qint64 row);

private:
    void controlsChanged();
    // The entry holding data.csv row `row` (a composable image set's layer).
    std::optional<std::size_t> entryOfRow(std::size_t row) const;
    std::size_t firstEntry(std::int64_t selectRow, const QString& selectParameters) const;
    void startThumbnails();
    const darkroom::Registry& registry_;
    std::optional<darkroom::CinemaDatabase> db_;
    std::vector<CinemaEntry> entries_;
    std::size_t entry_ = 0;
    bool composable_ = false;
    QLabel* title_;
    QFormLayout* form_;
    QListWidget* list_;
    std::vector<std::pair<std::size_t, QWidget*>> controls_;  // column, control
    std::shared_ptr<std::atomic<bool>> stop_;
    bool updating_ = false;
    int failures_ = 0;
};

}  // namespace editor
