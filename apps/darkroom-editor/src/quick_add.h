#pragma once
// The Tab menu of the graph view: a small popup at the cursor with a search
// field over every registered node type (as in Nuke, Houdini or Blender's
// Shift+A search). Typing filters by type or category, Up/Down choose,
// Enter adds, Escape or a click elsewhere closes.
#include <darkroom/core/registry.h>

#include <QFrame>

class QLineEdit;
class QListWidget;

namespace editor {

class QuickAdd : public QFrame {
    Q_OBJECT
public:
    explicit QuickAdd(const darkroom::Registry& registry, QWidget* parent = nullptr);
    // Opens with an empty search at `globalPos` (the cursor).
    void popup(QPoint globalPos);
    QLineEdit* search() const { return search_; }
    QListWidget* list() const { return list_; }

signals:
    void chosen(const QString& type);

protected:
    bool eventFilter(QObject* watched, QEvent* e) override;

private:
    void filter(const QString& text);
    void choose();
    QLineEdit* search_;
    QListWidget* list_;
};

}  // namespace editor
