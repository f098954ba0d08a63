#pragma once
// The Cinema browser: open a .cdb, choose an entry with one slider (numeric)
// or combo (text) per parameter column, or by clicking its thumbnail.
// Thumbnails are made on a pool thread, one at a time, and arrive as they
// are ready; opening another database drops the rest.
#include <darkroom/framework/cinema/database.h>

#include <QWidget>

#include <atomic>
#include <memory>
#include <optional>

class QLabel;
class QListWidget;
class QFormLayout;

namespace editor {

class CinemaPanel : public QWidget {
    Q_OBJECT
public:
    explicit CinemaPanel(QWidget* parent = nullptr);
    ~CinemaPanel() override;
    bool open(const QString& path, QString* error);
    const darkroom::CinemaDatabase* database() const { return db_ ? &*db_ : nullptr; }
    std::size_t currentRow() const { return row_; }
    void selectRow(std::size_t row);  // moves the controls and emits entryChosen
    QListWidget* thumbnails() const { return list_; }
    // Controls per parameter column (a QSlider or a QComboBox), for tests.
    QWidget* control(const QString& column) const;

signals:
    // The database folder and the entry as "name=value, ..." for CinemaReader.
    void entryChosen(const QString& database, const QString& parameters);

private:
    void controlsChanged();
    void startThumbnails();
    std::optional<darkroom::CinemaDatabase> db_;
    std::size_t row_ = 0;
    QLabel* title_;
    QFormLayout* form_;
    QListWidget* list_;
    std::vector<std::pair<std::size_t, QWidget*>> controls_;  // column, control
    std::shared_ptr<std::atomic<bool>> stop_;
    bool updating_ = false;
};

}  // namespace editor
