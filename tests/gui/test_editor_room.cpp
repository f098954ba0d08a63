// Room to work: the render view is the largest area, the Cinema dock shows
// up with a database, a loaded graph is fitted at a readable zoom, the
// layout is remembered, Tab opens the quick-add menu at the cursor, and
// dragging a connection off an input disconnects (or moves) it.
#include "cinema_panel.h"
#include "document.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "gui_support.h"
#include "main_window.h"
#include "node_item.h"
#include "quick_add.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/data/image_io.h>

#include <QDockWidget>
#include <QSettings>
#include <QStatusBar>
#include <QLineEdit>
#include <QListWidget>
#include <QScreen>
#include <QtTest>

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
  grey:
    type: ColorMapping
    parameters:
      channel: value
      colormap: grayscale
  write:
    type: ImageWriter
    parameters:
      path: out.png
edges:
  - read.image -> colour.image
  - colour.image -> write.image
)";

int area(const QWidget* w) { return w->isVisible() ? w->width() * w->height() : 0; }

}  // namespace

class RoomTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void renderViewIsTheLargestArea();
    void cinemaDockAppearsWithADatabase();
    void layoutIsRemembered();
    void loadedGraphIsFittedAtAReadableZoom();
    void tabOpensQuickAddAtTheCursor();
    void draggingOffAnInputDisconnects();
    void droppingOnAnotherInputMovesTheConnection();

private:
    void makeWindow();
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
    QString pipeline_;
};

void RoomTest::initTestCase() { guitest::prepare(); }

void RoomTest::init() {
    guitest::clearSettings();
    dir_ = std::make_unique<test::TempDir>();
    auto img = test::makeImage(64, 32, {"value"}, [](int x, int y, int) { return float(x + y) / 94.0f; });
    writeImage(*img, dir_->file("scalar.exr"));
    test::writeText(dir_->file("p.yaml"), kPipeline);
    pipeline_ = QString::fromStdString(dir_->file("p.yaml"));
    makeWindow();
}

void RoomTest::makeWindow() {
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
}

void RoomTest::cleanup() {
    w_->document()->undoStack()->setClean();
    w_.reset();
    dir_.reset();
}

void RoomTest::renderViewIsTheLargestArea() {
    QVERIFY(w_->openPipeline(pipeline_));
    QVERIFY(guitest::waitIdle(*w_));
    const int render = area(w_->renderView());
    QVERIFY2(render > area(w_->graphView()), qPrintable(QStringLiteral("render %1 graph %2").arg(render).arg(area(w_->graphView()))));
    for (const char* d : {"palette", "cinema", "log", "graph"})
        QVERIFY2(render > area(w_->dock(d)), d);
    // Most of the window's width, and a good part of its height.
    QVERIFY(w_->renderView()->width() > w_->width() * 3 / 4);
    QVERIFY(w_->renderView()->height() > w_->height() * 2 / 5);
    QVERIFY(!w_->dock("cinema")->isVisible());  // no database open
    QVERIFY(guitest::screenshot(w_.get(), "room-default-layout"));
}

void RoomTest::cinemaDockAppearsWithADatabase() {
    QVERIFY(!w_->dock("cinema")->isVisible());
    const std::string cdb = dir_->file("t.cdb");
    QDir().mkpath(QString::fromStdString(cdb));
    writeImage(*test::makeImage(16, 8, {"R", "G", "B"}, [](int x, int, int c) { return c == 0 ? x / 15.0f : 0.3f; }),
               cdb + "/a.exr");
    test::writeText(cdb + "/data.csv", "theta,FILE\n0,a.exr\n");
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    QVERIFY(w_->dock("cinema")->isVisible());
    QVERIFY(guitest::waitIdle(*w_));
    // Still the largest area with the browser open.
    QVERIFY(area(w_->renderView()) > area(w_->dock("cinema")));
    QVERIFY(guitest::screenshot(w_.get(), "room-cinema-dock"));
}

void RoomTest::layoutIsRemembered() {
    w_->resize(1300, 820);
    QTest::qWait(50);
    const int graphHeight = w_->dock("graph")->height();
    w_->dock("palette")->hide();
    w_->resizeDocks({w_->dock("graph")}, {graphHeight + 120}, Qt::Vertical);
    QTest::qWait(50);
    const int wanted = w_->dock("graph")->height();
    QVERIFY(std::abs(wanted - graphHeight) > 60);
    QVERIFY(w_->close());  // closing saves the layout
    makeWindow();
    QTest::qWait(50);
    QCOMPARE(w_->size(), QSize(1300, 820));
    QVERIFY(!w_->dock("palette")->isVisible());
    QVERIFY2(std::abs(w_->dock("graph")->height() - wanted) <= 4,
             qPrintable(QStringLiteral("%1 vs %2").arg(w_->dock("graph")->height()).arg(wanted)));
    QVERIFY(!w_->dock("cinema")->isVisible());
    // A saved layout from another version of the docks is ignored.
    QSettings().setValue("layout/version", 1);
    QVERIFY(!w_->restoreLayout());
}

void RoomTest::loadedGraphIsFittedAtAReadableZoom() {
    // The demo pipeline: 13 nodes, wider than the graph dock at any readable zoom.
    QVERIFY(w_->openPipeline(QStringLiteral(DARKROOM_SOURCE_DIR "/docs/examples/demo.yaml")));
    const double z = w_->graphView()->zoom();
    QVERIFY2(z >= editor::GraphView::kReadableZoom && z <= 1.0, qPrintable(QString::number(z)));
    // It starts at the sources: the first reader's title is in view.
    const QRect title = w_->graphView()->mapFromScene(w_->scene()->nodeItem("surface")->sceneBoundingRect()).boundingRect();
    QVERIFY(w_->graphView()->viewport()->rect().contains(title.topLeft()));
    QVERIFY(guitest::screenshot(w_->graphView(), "room-demo-graph"));
    // A small graph is shown whole, never blown up past 1:1.
    QVERIFY(w_->openPipeline(pipeline_));
    QVERIFY(w_->graphView()->zoom() <= 1.0);
    QVERIFY(w_->graphView()->zoom() >= editor::GraphView::kReadableZoom);
    for (const char* n : {"read", "colour", "write"}) {
        const QRect r = w_->graphView()->mapFromScene(w_->scene()->nodeItem(n)->sceneBoundingRect()).boundingRect();
        QVERIFY2(w_->graphView()->viewport()->rect().intersects(r), n);
    }
    QVERIFY(guitest::waitIdle(*w_));
}

void RoomTest::tabOpensQuickAddAtTheCursor() {
    QVERIFY(w_->openPipeline(pipeline_));
    QVERIFY(guitest::waitIdle(*w_));
    editor::GraphView* gv = w_->graphView();
    QWidget* vp = gv->viewport();
    const int menuWidth = w_->quickAdd()->width();
    // Empty background just right of the nodes, with room for the menu.
    const QPoint at = gv->mapFromScene(w_->scene()->itemsBoundingRect().topRight()) + QPoint(40, 30);
    QVERIFY(vp->rect().contains(at) && vp->mapToGlobal(at).x() + menuWidth < gv->screen()->availableGeometry().right());
    QTest::mouseMove(vp, at);
    gv->setFocus();
    QTest::keyClick(gv, Qt::Key_Tab);
    editor::QuickAdd* menu = w_->quickAdd();
    QVERIFY(menu->isVisible());
    QVERIFY2((menu->pos() - vp->mapToGlobal(at)).manhattanLength() < 4,
             qPrintable(QStringLiteral("menu at %1,%2").arg(menu->pos().x()).arg(menu->pos().y())));
    QVERIFY(guitest::screenshot(w_.get(), "room-quick-add"));
    QTest::keyClicks(menu->search(), "ssa");
    QCOMPARE(menu->list()->currentItem()->data(Qt::UserRole).toString(), QString("SSAO"));
    QTest::keyClick(menu->search(), Qt::Key_Return);
    QVERIFY(!menu->isVisible());
    const Node* n = w_->document()->graph().node("ssao");
    QVERIFY(n);
    // Placed where the cursor was: the title under it.
    const QRect r = gv->mapFromScene(w_->scene()->nodeItem("ssao")->sceneBoundingRect()).boundingRect();
    QVERIFY2(r.contains(at), qPrintable(QStringLiteral("node at %1,%2").arg(r.x()).arg(r.y())));
    QVERIFY2(r.top() < at.y() && at.y() - r.top() < 40, qPrintable(QStringLiteral("top %1 cursor %2").arg(r.top()).arg(at.y())));
    // Escape closes without adding.
    QTest::keyClick(gv, Qt::Key_Tab);
    QVERIFY(menu->isVisible());
    QTest::keyClick(menu->search(), Qt::Key_Escape);
    QVERIFY(!menu->isVisible());
    QCOMPARE(w_->document()->graph().nodes().size(), std::size_t(5));
}

void RoomTest::draggingOffAnInputDisconnects() {
    QVERIFY(w_->openPipeline(pipeline_));
    QVERIFY(guitest::waitIdle(*w_));
    QWidget* vp = w_->graphView()->viewport();
    const QPoint in = guitest::portPos(*w_, "write", "image", false);
    QVERIFY(vp->rect().contains(in));
    const QPoint away = in + QPoint(0, -120);
    QTest::mousePress(vp, Qt::LeftButton, {}, in);
    QTest::mouseMove(vp, in + QPoint(-20, -40));
    QTest::mouseMove(vp, away);
    QVERIFY(guitest::screenshot(w_->graphView(), "room-connection-picked-up"));
    QTest::mouseRelease(vp, Qt::LeftButton, {}, away);
    QVERIFY(w_->document()->graph().edgesInto("write", "image").empty());
    QCOMPARE(w_->document()->graph().edges().size(), std::size_t(1));
    w_->document()->undoStack()->undo();
    QCOMPARE(w_->document()->graph().edgesInto("write", "image").size(), std::size_t(1));
    // A press and release on the input without moving away changes nothing.
    QTest::mousePress(vp, Qt::LeftButton, {}, in);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, in);
    QCOMPARE(w_->document()->graph().edgesInto("write", "image").size(), std::size_t(1));
    QCOMPARE(w_->document()->undoStack()->count(), 1);
}

void RoomTest::droppingOnAnotherInputMovesTheConnection() {
    QVERIFY(w_->openPipeline(pipeline_));
    QVERIFY(guitest::waitIdle(*w_));
    QWidget* vp = w_->graphView()->viewport();
    const QPoint from = guitest::portPos(*w_, "colour", "image", false);
    const QPoint to = guitest::portPos(*w_, "grey", "image", false);
    QVERIFY(vp->rect().contains(from) && vp->rect().contains(to));
    QTest::mousePress(vp, Qt::LeftButton, {}, from);
    QTest::mouseMove(vp, (from + to) / 2);
    QTest::mouseMove(vp, to);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, to);
    const Graph& g = w_->document()->graph();
    QVERIFY(g.edgesInto("colour", "image").empty());
    QCOMPARE(g.edgesInto("grey", "image").size(), std::size_t(1));
    QCOMPARE(g.edgesInto("grey", "image")[0].from.str(), std::string("read.image"));
    // One undo step puts it back.
    w_->document()->undoStack()->undo();
    QCOMPARE(w_->document()->graph().edgesInto("colour", "image").size(), std::size_t(1));
    QVERIFY(w_->document()->graph().edgesInto("grey", "image").empty());
    // Dropped on a type that does not fit: refused, the connection stays.
    const QPoint opacity = guitest::portPos(*w_, "grey", "opacity", false);
    QTest::mousePress(vp, Qt::LeftButton, {}, from);
    QTest::mouseMove(vp, opacity);
    QTest::mouseRelease(vp, Qt::LeftButton, {}, opacity);
    QCOMPARE(w_->document()->graph().edgesInto("colour", "image").size(), std::size_t(1));
    QVERIFY(w_->statusBar()->currentMessage().contains("Cannot connect read.image to grey.opacity"));
}

QTEST_MAIN(RoomTest)
#include "test_editor_room.moc"
