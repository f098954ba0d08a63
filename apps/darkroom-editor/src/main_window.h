#pragma once
// The editor window. The render view is the central widget, the largest
// area (like Blender's compositor backdrop or Inviwo's canvas); the graph
// is a dock along the bottom, the palette a narrow dock on the left, the
// Cinema browser appears on the right when a database is opened, and the
// log is a tab beside the graph. Window and dock layout are remembered
// (QSettings). Every edit is evaluated live (evaluation.h).
#include <darkroom/diagnostics.h>
#include <darkroom/core/registry.h>

#include <QMainWindow>
#include <QTimer>

#include "autosave.h"

#include <functional>
#include <map>
#include <optional>

class QComboBox;
class QDockWidget;
class QLabel;
class QMenu;
class QPlainTextEdit;

class QToolButton;

namespace darkroom {
struct Node;
}

namespace editor {

class Autosave;
class CinemaPanel;
class ExplorerPanel;
class Document;
class Evaluation;
class GraphScene;
class GraphView;
class Palette;
class QuickAdd;
class RenderView;
struct EvalResult;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    MainWindow(const darkroom::Registry& registry, const darkroom::Diagnostics& pluginProblems,
               QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return doc_; }
    Autosave* autosave() const { return autosave_; }
    GraphScene* scene() const { return scene_; }
    GraphView* graphView() const { return graphView_; }
    RenderView* renderView() const { return render_; }
    Palette* palette() const { return palette_; }
    CinemaPanel* cinema() const { return cinema_; }
    ExplorerPanel* explorer() const { return explorer_; }
    QuickAdd* quickAdd() const { return quickAdd_; }
    Evaluation* evaluation() const { return eval_; }
    QPlainTextEdit* log() const { return log_; }
    QDockWidget* dock(const QString& objectName) const;
    QString displayedNode() const { return shownNode_; }
    // The status bar's frame line: size, time, the nodes that ran.
    QString frameText() const;

    // File operations; failures are logged and shown, never thrown.
    bool openPipeline(const QString& path);
    bool savePipeline(const QString& path);
    // `select`: the entry to choose (CinemaReader's `parameters`), else the first.
    // `selectRow`, `selectParameters`: the entry to show first (CinemaPanel::open).
    bool openCinema(const QString& path, std::int64_t selectRow = -1, const QString& selectParameters = {});
    bool exportView(const QString& path);  // .exr: the buffer's channels; else the view as 8-bit
    // Adds a node of `type` and selects it: with its title at `scenePos`, or
    // right of the existing nodes.
    QString addNode(const QString& type, std::optional<QPointF> scenePos = std::nullopt);
    void logMessage(const QString& text);
    // At the start: offers back the autosave of the session that crashed
    // last (`ask` answers the question; default a message box) and sets the
    // older ones aside (File > Recover autosave).
    void offerRecovery(const std::function<bool(const Recovery&)>& ask = {});
    void updateRecoverMenu();
    // Bumped when docks are added or renamed: an older saved layout is ignored.
    static constexpr int kLayoutVersion = 3;
    // Window geometry and dock layout to and from QSettings (closing saves,
    // the first show restores).
    void saveLayout() const;
    bool restoreLayout();

signals:
    void evaluated();  // a result (image or error) reached the render view
    // The frame of evaluation `generation` is on screen (level 0 = settled
    // at full resolution, k = preview at 1/2^k).
    void framePresented(std::uint64_t generation, int level);

protected:
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;
    void closeEvent(QCloseEvent* e) override;
    void showEvent(QShowEvent* e) override;

private:
    void buildMenus();
    QToolButton* buildRenderPane();
    void buildDocks(const darkroom::Registry& registry);
    void connectParts(QToolButton* fit);
    void scheduleEvaluation();
    void onEvaluated(const EvalResult& r);
    bool showWaiting(const QString& node, const QString& target);
    // A path as a node's input means it: relative to the pipeline's folder.
    QString absoluteInput(const QString& path) const;
    void onEntryChosen(const QString& database, qint64 row);
    bool readsRow(const darkroom::Node& reader, qint64 row) const;
    void addRecent(const QString& path);
    void updateRecentMenu();
    void updateTitle();
    bool maybeSave();
    bool recover(const Recovery& r);
    void buildHelpMenu();
    void buildExplorer(const darkroom::Registry& registry);
    QString explorerReader() const;  // the CinemaReader reading the explorer's database
    void saveExplorerState();
    void syncExplorerFromDocument();
    void restoreExplorer();
    void updateExplorerPipeline();

    Document* doc_;
    Autosave* autosave_;
    GraphScene* scene_;
    GraphView* graphView_;
    RenderView* render_;
    QComboBox* channel_;
    QComboBox* layer_;  // hidden unless the shown buffer has layers
    Palette* palette_;
    CinemaPanel* cinema_;
    ExplorerPanel* explorer_ = nullptr;
    QTimer explorerPipelineTimer_;
    QuickAdd* quickAdd_;
    QPlainTextEdit* log_;
    Evaluation* eval_;
    QLabel* probe_;
    QLabel* timing_;
    QMenu* recentMenu_ = nullptr;
    QMenu* recoverMenu_ = nullptr;
    QString shownNode_;
    QString shownTarget_, shownPort_;  // the image output on screen (or asked for)
    QString lastRequest_;  // graph revision, node, port, folder of the last evaluation asked for
    bool restored_ = false;   // the layout came from QSettings
    bool waiting_ = false;    // the shown part waits for input: results in flight are not shown
    bool shownOnce_ = false;
    std::uint64_t tag_ = 0;
    std::map<std::uint64_t, std::pair<std::uint64_t, int>> tags_;  // render tag -> generation, level
};

}  // namespace editor
