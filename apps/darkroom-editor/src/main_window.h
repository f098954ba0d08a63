#pragma once
// The editor window: graph view and render view side by side, the palette,
// Cinema browser and log as docks, menus for files and editing, and the
// live evaluation that follows every change.
#include <darkroom/framework/diagnostics.h>
#include <darkroom/framework/registry.h>

#include <QMainWindow>

class QComboBox;
class QLabel;
class QMenu;
class QPlainTextEdit;

namespace editor {

class CinemaPanel;
class Document;
class Evaluation;
class GraphScene;
class GraphView;
class Palette;
class RenderView;
struct EvalResult;

class MainWindow : public QMainWindow {
    Q_OBJECT
public:
    MainWindow(const darkroom::Registry& registry, const darkroom::Diagnostics& pluginProblems,
               QWidget* parent = nullptr);
    ~MainWindow() override;

    Document* document() const { return doc_; }
    GraphScene* scene() const { return scene_; }
    GraphView* graphView() const { return graphView_; }
    RenderView* renderView() const { return render_; }
    Palette* palette() const { return palette_; }
    CinemaPanel* cinema() const { return cinema_; }
    Evaluation* evaluation() const { return eval_; }
    QPlainTextEdit* log() const { return log_; }
    QString displayedNode() const { return shownNode_; }

    // File operations; failures are logged and shown, never thrown.
    bool openPipeline(const QString& path);
    bool savePipeline(const QString& path);
    bool openCinema(const QString& path);
    bool exportView(const QString& path);  // .exr: the buffer's channels; else the view as 8-bit
    // Adds a node of `type` at the centre of the graph view and selects it.
    QString addNode(const QString& type);
    void logMessage(const QString& text);

signals:
    void evaluated();  // a result (image or error) reached the render view

protected:
    void dragEnterEvent(QDragEnterEvent* e) override;
    void dropEvent(QDropEvent* e) override;
    void closeEvent(QCloseEvent* e) override;

private:
    void buildMenus();
    void scheduleEvaluation();
    void onEvaluated(const EvalResult& r);
    void onEntryChosen(const QString& database, const QString& parameters);
    void addRecent(const QString& path);
    void updateRecentMenu();
    void updateTitle();
    bool maybeSave();

    Document* doc_;
    GraphScene* scene_;
    GraphView* graphView_;
    RenderView* render_;
    QComboBox* channel_;
    Palette* palette_;
    CinemaPanel* cinema_;
    QPlainTextEdit* log_;
    Evaluation* eval_;
    QLabel* probe_;
    QLabel* timing_;
    QMenu* recentMenu_ = nullptr;
    QString shownNode_;
    QString lastRequest_;  // graph revision, node, port, folder of the last evaluation asked for
};

}  // namespace editor
