#pragma once
// Crash recovery. A plugin that crashes inside execute() takes the editor
// down with it (a signal cannot be caught safely in-process), so the graph
// with unsaved changes is written to an autosave file a second after every
// edit: <app data>/autosave/<pid>.yaml, atomically, the pipeline's own path in
// its first line. A clean exit, a save or undoing back to the saved state
// removes it. At the next start, the autosave of the editor that ended last
// without a clean exit (the session that crashed) is offered back; older
// ones left behind were offered at earlier starts, or crashed beside it, and
// are set aside into <autosave>/older, listed under File > Recover autosave.
#include <QObject>
#include <QString>
#include <QTimer>

#include <vector>

namespace editor {

class Document;

struct Recovery {
    QString file;          // the autosave file
    QString originalPath;  // the pipeline it was edited from (empty: never saved)
    QString savedAt;       // when it was written, for the question to the user
};

class Autosave : public QObject {
    Q_OBJECT
public:
    explicit Autosave(Document* doc, QObject* parent = nullptr);
    ~Autosave() override;

    // Writes now (tests; the timer does it a second after an edit).
    void writeNow();
    // The file this editor writes ("" until it has written one).
    const QString& file() const { return file_; }
    // Removes this editor's autosave (clean exit).
    void discard();

    // Autosaves left by editors that are not running any more, newest first.
    static std::vector<Recovery> leftBehind();
    // Loads a recovery into `doc` as an unsaved edit of its original
    // pipeline; removes the autosave file. False (with messages) on failure.
    static bool restore(const Recovery& r, Document* doc, QStringList& messages);
    // Removes an autosave file the user chose not to restore.
    static void drop(const Recovery& r);
    // Moves an autosave into the set-aside folder: no longer offered at a
    // start, still restorable from the File menu.
    static void putAside(const Recovery& r);
    // The set-aside autosaves, newest first.
    static std::vector<Recovery> setAside();
    static QString folder();

private:
    Document* doc_;
    QTimer timer_;
    QString file_;
};

}  // namespace editor
