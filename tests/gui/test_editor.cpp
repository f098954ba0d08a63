// The editor as a user drives it, under a virtual X server: open a
// pipeline, add a node from the palette, connect by dragging, move a slider
// and see the render view change, undo, save and reload, browse a Cinema
// database. Each test leaves a screenshot in tests/gui-artifacts/.
#include "cinema_panel.h"
#include "document.h"
#include "evaluation.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "gui_support.h"
#include "main_window.h"
#include "node_item.h"
#include "palette.h"
#include "param_widget.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/data/image_io.h>

#include <QDir>
#include <QDropEvent>
#include <QLineEdit>
#include <QListWidget>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QWindow>
#include <QtTest>

#include <memory>

using namespace darkroom;
using editor::MainWindow;

namespace {

const char* kPipeline = R"(darkroom: 1
nodes:
  read:
    type: ImageReader
    parameters:
      path: scalar.exr
  colour:
    type: ColorMapping
    parameters:
      channel: value
  write:
    type: ImageWriter
    parameters:
      path: out.png
edges:
  - read.image -> colour.image
  - colour.image -> write.image
)";

}  // namespace

class EditorTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void opensPipelineAndShowsImage();
    void fileDroppedOnTheRenderViewOpens();
    void paletteAddsNodeAndDragConnects();
    void refusedConnectionSaysWhy();
    void sliderChangesPixelsAndUndoRestores();
    void saveAndReloadGivesTheSameFile();
    void cinemaSlidersDriveTheReader();
    void badPipelineIsReportedNotFatal();

private:
    void waitForEvaluation();
    void screenshot(const QString& name);
    QPoint viewportPos(const QString& node, const QString& port, bool output);
    Registry registry_;
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
    QString pipeline_;
};

void EditorTest::initTestCase() {
    guitest::prepare();  // recent files and the layout go to a test settings folder
    const auto problems = registry_.loadPlugins({DARKROOM_PLUGIN_DIR});
    QVERIFY(registry_.filter("ColorMapping"));
    QVERIFY(registry_.filter("ImageReader"));
    QDir().mkpath(DARKROOM_GUI_ARTIFACTS);
}

void EditorTest::init() {
    dir_ = std::make_unique<test::TempDir>();
    auto img = test::makeImage(64, 32, {"value"}, [](int x, int y, int) { return float(x + y) / 94.0f; });
    writeImage(*img, dir_->file("scalar.exr"));
    test::writeText(dir_->file("p.yaml"), kPipeline);
    pipeline_ = QString::fromStdString(dir_->file("p.yaml"));
    w_ = std::make_unique<MainWindow>(registry_, Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
}

void EditorTest::cleanup() {
    w_->document()->undoStack()->setClean();  // no "save changes?" question
    w_.reset();
    dir_.reset();
}

void EditorTest::waitForEvaluation() {
    QTRY_VERIFY_WITH_TIMEOUT(!w_->evaluation()->busy(), 60000);
    QCoreApplication::processEvents();
    w_->renderView()->renderNow();
}

void EditorTest::screenshot(const QString& name) {
    // From the X server: the render view is a native OpenGL window, which
    // QWidget::grab() does not see.
    QVERIFY2(guitest::screenshot(w_.get(), name), qPrintable(name));
}

QPoint EditorTest::viewportPos(const QString& node, const QString& port, bool output) {
    return w_->graphView()->mapFromScene(w_->scene()->portPos(node, port, output));
}

void EditorTest::opensPipelineAndShowsImage() {
    QVERIFY(w_->openPipeline(pipeline_));
    waitForEvaluation();
    QCOMPARE(w_->document()->graph().nodes().size(), std::size_t(3));
    // No node selected: what the writer writes is shown.
    QCOMPARE(w_->displayedNode(), QString("write"));
    QVERIFY2(w_->frameText().startsWith("colour: 64 × 32"), qPrintable(w_->frameText()));
    const auto& img = w_->renderView()->image();
    QVERIFY(img);
    QCOMPARE(img->width(), 64);
    QVERIFY(img->hasChannel("R"));
    // Loaded without positions: laid out by depth, left to right.
    QVERIFY(w_->scene()->nodeItem("read")->x() < w_->scene()->nodeItem("colour")->x());
    QVERIFY(w_->scene()->nodeItem("colour")->x() < w_->scene()->nodeItem("write")->x());
    // The view is not blank: the colour-mapped ramp spans several colours.
    const QImage fb = w_->renderView()->grabFramebuffer();
    const QPoint c(fb.width() / 2, fb.height() / 2);
    QVERIFY(fb.pixel(c - QPoint(fb.width() / 4, 0)) != fb.pixel(c + QPoint(fb.width() / 4, 0)));
    screenshot("open-pipeline");
}

void EditorTest::fileDroppedOnTheRenderViewOpens() {
    // The render view is a native window of its own: what is dropped on it
    // reaches the main window as a drop anywhere else does.
    QWindow* view = w_->renderView()->surface();
    QMimeData data;
    data.setUrls({QUrl::fromLocalFile(pipeline_)});
    const QPointF at(view->width() / 2.0, view->height() / 2.0);
    QDragEnterEvent enter(at.toPoint(), Qt::CopyAction, &data, Qt::LeftButton, {});
    QCoreApplication::sendEvent(view, &enter);
    QVERIFY(enter.isAccepted());
    QDropEvent drop(at, Qt::CopyAction, &data, Qt::LeftButton, {});
    QCoreApplication::sendEvent(view, &drop);
    QCOMPARE(w_->document()->path(), pipeline_);
    waitForEvaluation();
    QVERIFY(w_->renderView()->image());
}

void EditorTest::paletteAddsNodeAndDragConnects() {
    QVERIFY(w_->openPipeline(pipeline_));
    waitForEvaluation();
    QTest::keyClicks(w_->palette()->search(), "ColorMapp");
    QTest::keyClick(w_->palette()->search(), Qt::Key_Return);
    QVERIFY(w_->document()->graph().node("colormapping"));
    QCOMPARE(w_->scene()->selectedNode(), QString("colormapping"));
    w_->graphView()->fitAll();
    QCoreApplication::processEvents();

    QWidget* vp = w_->graphView()->viewport();
    const QPoint from = viewportPos("read", "image", true), to = viewportPos("colormapping", "image", false);
    QVERIFY(vp->rect().contains(from) && vp->rect().contains(to));
    QTest::mousePress(vp, Qt::LeftButton, {}, from);
    QTest::mouseMove(vp, (from + to) / 2);
    QTest::mouseMove(vp, to);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, to);
    const auto edges = w_->document()->graph().edgesInto("colormapping", "image");
    QCOMPARE(edges.size(), std::size_t(1));
    QCOMPARE(edges[0].from.str(), std::string("read.image"));
    waitForEvaluation();
    screenshot("palette-and-drag");
    // Undo removes the edge, then the node.
    w_->document()->undoStack()->undo();
    QVERIFY(w_->document()->graph().edgesInto("colormapping", "image").empty());
    w_->document()->undoStack()->undo();
    QVERIFY(!w_->document()->graph().node("colormapping"));
    QVERIFY(!w_->scene()->nodeItem("colormapping"));
}

void EditorTest::refusedConnectionSaysWhy() {
    QVERIFY(w_->openPipeline(pipeline_));
    waitForEvaluation();
    w_->graphView()->fitAll();
    QCoreApplication::processEvents();
    QWidget* vp = w_->graphView()->viewport();
    const std::size_t before = w_->document()->graph().edges().size();
    const QPoint from = viewportPos("read", "image", true), to = viewportPos("colour", "opacity", false);
    QTest::mousePress(vp, Qt::LeftButton, {}, from);
    QTest::mouseMove(vp, to);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, to);
    QCOMPARE(w_->document()->graph().edges().size(), before);
    const QString msg = w_->statusBar()->currentMessage();
    QVERIFY2(msg.contains("Cannot connect read.image to colour.opacity"), qPrintable(msg));
    screenshot("refused-connection");
}

void EditorTest::sliderChangesPixelsAndUndoRestores() {
    QVERIFY(w_->openPipeline(pipeline_));
    waitForEvaluation();
    const QImage before = w_->renderView()->grabFramebuffer();
    const auto readRuns = w_->evaluation()->executions("read");
    const auto colourRuns = w_->evaluation()->executions("colour");

    editor::ParamWidget* opacity = w_->scene()->nodeItem("colour")->paramWidget("opacity");
    QVERIFY(opacity && opacity->slider());
    QCOMPARE(opacity->slider()->value(), opacity->slider()->maximum());
    // Drag the slider handle from the right end to the left end.
    QSlider* s = opacity->slider();
    s->setFocus();
    QTest::keyClick(s, Qt::Key_Home);  // the keyboard moves a slider as a drag does
    waitForEvaluation();
    QCOMPARE(w_->document()->graph().node("colour")->parameter("opacity")->asFloat(), 0.0);
    const QImage after = w_->renderView()->grabFramebuffer();
    QVERIFY(after != before);
    // Only the dirty node ran again; the reader's result came from the cache.
    QCOMPARE(w_->evaluation()->executions("read"), readRuns);
    const auto colourAfter = w_->evaluation()->executions("colour");
    QVERIFY(colourAfter > colourRuns);
    screenshot("slider-opacity-0");

    w_->document()->undoStack()->undo();
    waitForEvaluation();
    QCOMPARE(s->value(), s->maximum());
    QCOMPARE(w_->renderView()->grabFramebuffer(), before);
    // Undo changed only the colour node: the reader still did not run again.
    QCOMPARE(w_->evaluation()->executions("read"), readRuns);
    QVERIFY(w_->evaluation()->executions("colour") > colourAfter);
}

void EditorTest::saveAndReloadGivesTheSameFile() {
    QVERIFY(w_->openPipeline(pipeline_));
    waitForEvaluation();
    const QString a = QString::fromStdString(dir_->file("a.yaml")), b = QString::fromStdString(dir_->file("b.yaml"));
    QVERIFY(w_->savePipeline(a));
    QVERIFY(w_->openPipeline(a));
    waitForEvaluation();
    QVERIFY(w_->savePipeline(b));
    const std::string ta = test::readText(a.toStdString()), tb = test::readText(b.toStdString());
    QVERIFY(!ta.empty());
    QCOMPARE(tb, ta);
    QVERIFY2(ta.find("ui: {position: [") != std::string::npos, ta.c_str());
    // The laid-out positions came back exactly.
    QCOMPARE(w_->scene()->nodeItem("colour")->pos(), QPointF(300, 0));
    screenshot("save-reload");
}

void EditorTest::cinemaSlidersDriveTheReader() {
    if (!registry_.filter("CinemaReader")) QSKIP("CinemaReader plugin not built");
    // A two-entry database: theta 0 is red, theta 30 is blue.
    const std::string cdb = dir_->file("t.cdb");
    QDir().mkpath(QString::fromStdString(cdb));
    for (int t : {0, 30}) {
        auto img = test::makeImage(32, 16, {"R", "G", "B"}, [t](int, int, int c) {
            return float((c == 0 && t == 0) || (c == 2 && t == 30));
        });
        writeImage(*img, cdb + "/theta=" + std::to_string(t) + ".exr");
    }
    test::writeText(cdb + "/data.csv", "theta,FILE\n0,theta=0.exr\n30,theta=30.exr\n");
    w_->document()->clear();
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    // No reader in the graph: the browser adds one and feeds it.
    const Node* reader = w_->document()->graph().node("cinemareader");
    QVERIFY(reader);
    QCOMPARE(reader->parameter("entry")->asInt(), 0);  // the row number, as --foreach gives it
    waitForEvaluation();
    QVERIFY(w_->renderView()->image());
    const float red = w_->renderView()->image()->hostFloat("R")[0];
    QCOMPARE(red, 1.0f);
    auto* slider = qobject_cast<QSlider*>(w_->cinema()->control("theta"));
    QVERIFY(slider);
    slider->setValue(1);
    QCOMPARE(w_->document()->graph().node("cinemareader")->parameter("entry")->asInt(), 1);
    waitForEvaluation();
    QCOMPARE(w_->renderView()->image()->hostFloat("B")[0], 1.0f);
    QCOMPARE(w_->renderView()->image()->hostFloat("R")[0], 0.0f);
    // Thumbnails arrive from the pool thread.
    QTRY_VERIFY_WITH_TIMEOUT(w_->cinema()->thumbnails()->item(1)->data(Qt::UserRole).toBool(), 30000);
    screenshot("cinema");
}

void EditorTest::badPipelineIsReportedNotFatal() {
    test::writeText(dir_->file("bad.yaml"), "darkroom: 1\nnodes:\n  a: [unclosed\n");
    QVERIFY(!w_->openPipeline(QString::fromStdString(dir_->file("bad.yaml"))));
    QVERIFY2(w_->log()->toPlainText().contains("bad.yaml"), qPrintable(w_->log()->toPlainText()));
    // A node failing at run time turns red and names the problem.
    test::writeText(dir_->file("missing.yaml"), "darkroom: 1\nnodes:\n  read:\n    type: ImageReader\n"
                                                "    parameters:\n      path: nowhere.exr\n");
    QVERIFY(w_->openPipeline(QString::fromStdString(dir_->file("missing.yaml"))));
    waitForEvaluation();
    QVERIFY(w_->scene()->nodeItem("read")->toolTip().contains("nowhere.exr"));
    screenshot("node-error");
}

QTEST_MAIN(EditorTest)
#include "test_editor.moc"
