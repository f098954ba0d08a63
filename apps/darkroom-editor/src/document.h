#pragma once
// The edited pipeline: the Graph, its file, and the undo stack. Every edit
// goes through edit(), which applies a function to a copy of the graph and
// pushes a command holding the graph before and after. Copies keep node
// versions, so undo re-runs only the nodes the undone edit touched.
#include <darkroom/core/graph.h>

#include <QObject>
#include <QString>
#include <QUndoStack>

#include <functional>

namespace editor {

class Document : public QObject {
    Q_OBJECT
public:
    explicit Document(const darkroom::Registry& registry, QObject* parent = nullptr);

    const darkroom::Registry& registry() const { return *registry_; }
    const darkroom::Graph& graph() const { return graph_; }
    QUndoStack* undoStack() { return &undo_; }
    const QString& path() const { return path_; }
    QString folder() const;  // relative paths in the pipeline resolve here

    // Applies `fn` to a copy; on darkroom::Error nothing changes and the
    // message is returned. Consecutive edits with the same non-empty
    // `mergeKey` (a slider drag, a node move) become one undo step.
    QString edit(const QString& text, const std::function<void(darkroom::Graph&)>& fn,
                 const QString& mergeKey = {});
    void replaceGraph(darkroom::Graph g);  // used by the undo command

    void clear();
    // Problems found while loading (file:line:column) go to `messages`;
    // returns false when the file could not be read at all.
    bool load(const QString& path, QStringList& messages);
    bool save(const QString& path, QString* error);
    // Replaces the graph with pipeline text recovered from an autosave
    // (`source` names it in messages), as an unsaved edit of `originalPath`
    // (relative paths resolve there). False when nothing could be read.
    bool restore(const QString& text, const QString& originalPath, const QString& source, QStringList& messages);
    QString uniqueName(const QString& base) const;

signals:
    void changed();       // any change of the graph (edit, undo, load)
    void pathChanged();

private:
    const darkroom::Registry* registry_;
    darkroom::Graph graph_;
    QUndoStack undo_;
    QString path_;
};

}  // namespace editor
