#pragma once
// Every registered filter type grouped by category, with a search box:
// typing filters the list, Enter adds the first match, double-click adds
// the one clicked.
#include <darkroom/core/registry.h>

#include <QWidget>

class QLineEdit;
class QTreeWidget;

namespace editor {

class Palette : public QWidget {
    Q_OBJECT
public:
    explicit Palette(const darkroom::Registry& registry, QWidget* parent = nullptr);
    QLineEdit* search() const { return search_; }
    QTreeWidget* tree() const { return tree_; }
    void focusSearch();

signals:
    void addRequested(const QString& type);

private:
    void filter(const QString& text);
    QLineEdit* search_;
    QTreeWidget* tree_;
};

}  // namespace editor
