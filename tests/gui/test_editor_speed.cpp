// Slider-speed feedback: reduced-resolution previews while a value is
// dragged, settling at full resolution when the hand stops, stale work
// cancelled (also a cancel that arrives as a run starts), and the frame
// time and the nodes that ran shown. Timing-free: the preview budget is set
// so that every frame counts as slow, and the checks are on what ran.
#include "document.h"
#include "evaluation.h"
#include "evaluator_adapter.h"
#include "graph_scene.h"
#include "gui_support.h"
#include "main_window.h"
#include "node_item.h"
#include "param_widget.h"
#include "preview_graph.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/error.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/data/image_io.h>

#include <QSlider>
#include <QStyleOptionSlider>
#include <QtTest>

#include <algorithm>
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
edges:
  - read.image -> colour.image
)";

QPoint handleCentre(QSlider* s) {
    QStyleOptionSlider opt;
    opt.initFrom(s);
    opt.subControls = QStyle::SC_All;
    opt.orientation = s->orientation();
    opt.minimum = s->minimum();
    opt.maximum = s->maximum();
    opt.sliderPosition = s->sliderPosition();
    opt.sliderValue = s->value();
    opt.singleStep = s->singleStep();
    opt.pageStep = s->pageStep();
    return s->style()->subControlRect(QStyle::CC_Slider, &opt, QStyle::SC_SliderHandle, s).center();
}

struct Shown {
    std::uint64_t generation;
    int level;
    int width;
};

}  // namespace

class SpeedTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void previewWhileDraggingThenSettles();
    void settlesWhenTheHandPauses();
    void staleRunsAreCancelledAndCancelsAreNotLost();
    void framesArriveInOrderEndingWithTheNewest();
    void frameTimeAndNodesThatRanAreShown();

private:
    QSlider* opacitySlider();
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
    std::vector<Shown> shown_;
};

void SpeedTest::initTestCase() {
    guitest::prepare();
    QVERIFY(guitest::registry().filter("Resize"));
}

void SpeedTest::init() {
    dir_ = std::make_unique<test::TempDir>();
    auto img = test::makeImage(256, 128, {"value"}, [](int x, int y, int) { return float(x + y) / 382.0f; });
    writeImage(*img, dir_->file("scalar.exr"));
    test::writeText(dir_->file("p.yaml"), kPipeline);
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
    shown_.clear();
    connect(w_.get(), &MainWindow::framePresented, this, [this](std::uint64_t g, int level) {
        const auto& img = w_->renderView()->image();
        shown_.push_back({g, level, img ? img->width() : 0});
    });
    QVERIFY(w_->openPipeline(QString::fromStdString(dir_->file("p.yaml"))));
    QVERIFY(guitest::waitIdle(*w_));
}

void SpeedTest::cleanup() {
    w_->document()->undoStack()->setClean();
    w_.reset();
    dir_.reset();
}

QSlider* SpeedTest::opacitySlider() {
    editor::ParamWidget* p = w_->scene()->nodeItem("colour")->paramWidget("opacity");
    return p ? p->slider() : nullptr;
}

void SpeedTest::previewWhileDraggingThenSettles() {
    editor::Evaluation* ev = w_->evaluation();
    const auto readRuns = ev->executions("read");
    const auto colourRuns = ev->executions("colour");
    ev->setPreviewBudget(1e-9);  // every frame is too slow: previews always
    QSlider* s = opacitySlider();
    QVERIFY(s);
    QPoint p = handleCentre(s);
    shown_.clear();
    QTest::mousePress(s, Qt::LeftButton, {}, p);
    QVERIFY(ev->interacting());
    const int moves = 12;
    bool screenshotTaken = false;
    for (int i = 0; i < moves; ++i) {
        p.rx() -= 6;
        QTest::mouseMove(s, p);
        QTest::qWait(30);
        if (!screenshotTaken && w_->renderView()->level() > 0) {
            w_->renderView()->renderNow();
            QVERIFY(guitest::screenshot(w_.get(), "speed-preview-while-dragging"));
            screenshotTaken = true;
        }
    }
    QVERIFY(QTest::qWaitFor([&] { return !shown_.empty() && shown_.back().level > 0; }, 20000));
    const double dragged = w_->document()->graph().node("colour")->parameter("opacity")->asFloat();
    QVERIFY(dragged < 1.0);
    QTest::mouseRelease(s, Qt::LeftButton, {}, p);
    QVERIFY(!ev->interacting());
    QVERIFY(guitest::waitIdle(*w_));

    // Previews were shown, at 1/2^level of the width, drawn over the full size.
    int previews = 0;
    for (const auto& f : shown_)
        if (f.level > 0) {
            ++previews;
            QCOMPARE(f.width, std::max(1, int(std::lround(256.0 / (1 << f.level)))));
        }
    QVERIFY(previews >= 1);
    // ... and the picture settled at full resolution, on the last value.
    QVERIFY(!shown_.empty());
    QCOMPARE(shown_.back().level, 0);
    QCOMPARE(shown_.back().width, 256);
    QCOMPARE(shown_.back().generation, ev->generation());
    QCOMPARE(w_->renderView()->level(), 0);
    Evaluator reference;
    EvaluatorOptions o;
    o.inputBase = dir_->path();
    reference.setOptions(o);
    const BufferPtr expected = reference.evaluateImage(w_->document()->graph(), "colour", "image");
    QVERIFY(identical(*expected, *w_->renderView()->image()));

    // The preview evaluator never read the source: it took the full
    // evaluator's result (shared sources). It downsampled it once per preview
    // size (a drag whose previews overrun the budget gets coarser, and the
    // warm-up after the first full frame may have used another size); only
    // the colour mapping ran again per preview.
    QCOMPARE(ev->previewExecutions("read"), std::uint64_t(0));
    // There are five preview sizes (1/2 to 1/32 of each side).
    const auto resized = ev->previewExecutions(QString::fromStdString(editor::previewNodeName("read", "image")));
    QVERIFY2(resized >= 1 && resized <= 5, qPrintable(QString("Resize ran %1 times").arg(resized)));
    QVERIFY(ev->previewExecutions("colour") >= std::uint64_t(previews));
    // The full-resolution evaluator kept its reader result and did not run per step.
    QCOMPARE(ev->executions("read"), readRuns);
    QVERIFY(ev->executions("colour") > colourRuns);
    QVERIFY(ev->executions("colour") - colourRuns < std::uint64_t(moves));
    QVERIFY(screenshotTaken);
    QVERIFY(guitest::screenshot(w_.get(), "speed-settled"));
}

void SpeedTest::settlesWhenTheHandPauses() {
    editor::Evaluation* ev = w_->evaluation();
    ev->setPreviewBudget(1e-9);
    ev->setSettleDelay(40);
    QSlider* s = opacitySlider();
    QPoint p = handleCentre(s);
    QTest::mousePress(s, Qt::LeftButton, {}, p);
    p.rx() -= 20;
    shown_.clear();
    QTest::mouseMove(s, p);
    // The button is still held: the frame settles after a pause of the hand.
    QVERIFY(QTest::qWaitFor([&] { return !shown_.empty() && shown_.back().level == 0; }, 20000));
    QVERIFY(ev->interacting());
    QCOMPARE(shown_.back().generation, ev->generation());
    QTest::mouseRelease(s, Qt::LeftButton, {}, p);
    QVERIFY(guitest::waitIdle(*w_));
}

void SpeedTest::staleRunsAreCancelledAndCancelsAreNotLost() {
    Graph g(guitest::registry());
    g.addNode("read", "ImageReader");
    g.setParameter("read", "path", Value(std::string("scalar.exr")));
    std::string last = "read";
    for (const char* r : {"r1", "r2", "r3"}) {
        g.addNode(r, "Resize");
        g.setParameter(r, "scale", Value(0.5));
        g.connect({last, "image"}, {r, "image"});
        last = r;
    }
    editor::EvaluatorAdapter a;
    a.setInputBase(dir_->path());
    // Stale before it starts: nothing runs.
    QVERIFY_THROWS_EXCEPTION(Cancelled, a.evaluate(g, "r3", "image", [] { return true; }, nullptr));
    QCOMPARE(a.executions("read"), std::uint64_t(0));
    // Stale from the moment it started (the evaluator clears a cancel flag
    // set before the run starts): caught as the first node finishes.
    int asked = 0;
    QVERIFY_THROWS_EXCEPTION(Cancelled, a.evaluate(g, "r3", "image", [&] { return ++asked > 1; }, nullptr));
    QVERIFY(asked > 1);
    QVERIFY(a.executions("read") <= 1);  // the cancel lands as (or right after) the reader finishes
    QCOMPARE(a.executions("r3"), std::uint64_t(0));
    // Current: runs to the end; the profile says what ran.
    editor::FrameProfile profile;
    const BufferPtr out = a.evaluate(g, "r3", "image", [] { return false; }, &profile);
    QVERIFY(out);
    QCOMPARE(out->width(), 32);
    QCOMPARE(profile.nodes.size(), std::size_t(4));
    QCOMPARE(profile.nodes.front().node, std::string("read"));
    QCOMPARE(profile.nodes.back().node, std::string("r3"));
    QVERIFY(profile.nodes.back().ran && profile.nodes.back().seconds > 0);
    QCOMPARE(a.evaluate(g, "r3", "image", {}, &profile)->width(), 32);
    QCOMPARE(profile.ran(), 0);  // all cached now
    // Nothing changed: nothing is predicted to run. A changed r2 predicts
    // the last times of r2 and r3, the nodes that will run again.
    QCOMPARE(a.predictSeconds(g, "r3"), 0.0);
    g.setParameter("r2", "scale", Value(0.25));
    QCOMPARE(a.predictSeconds(g, "r3"), a.lastSeconds("r2") + a.lastSeconds("r3"));
    a.evaluate(g, "r3", "image", {}, &profile);
    QCOMPARE(profile.ran(), 2);
    QVERIFY(!profile.nodes[0].ran && !profile.nodes[1].ran && profile.nodes[2].ran && profile.nodes[3].ran);
}

void SpeedTest::framesArriveInOrderEndingWithTheNewest() {
    editor::Evaluation* ev = w_->evaluation();
    std::vector<std::uint64_t> finished;
    connect(ev, &editor::Evaluation::finished, this,
            [&](const editor::EvalResult& r) { finished.push_back(r.generation); });
    Graph g = w_->document()->graph();
    const auto before = ev->executions("colour");
    std::uint64_t newest = 0;
    int requests = 0;
    // Quick edits (under the budget) are coalesced, slow ones (budget 0:
    // everything counts as slow) cancel the run in progress; either way
    // frames never go back in time and the last one is the newest edit.
    for (double budget : {10.0, 0.0}) {
        ev->setPreviewBudget(budget);
        finished.clear();
        for (double opacity : {0.2, 0.4, 0.6, 0.8}) {
            g.setParameter("colour", "opacity", Value(opacity + budget / 100));
            ev->request(g, "colour", "image", QString::fromStdString(dir_->path()));
            newest = ev->generation();
            ++requests;
        }
        QVERIFY(QTest::qWaitFor([&] { return !ev->busy(); }, 60000));
        QVERIFY(!finished.empty());
        QCOMPARE(finished.back(), newest);
        QVERIFY(std::is_sorted(finished.begin(), finished.end()));
        QVERIFY(std::adjacent_find(finished.begin(), finished.end()) == finished.end());
    }
    // Waiting requests were replaced, not queued: fewer runs than requests
    // is typical, more is impossible.
    QVERIFY(ev->executions("colour") - before <= std::uint64_t(requests));
    QCOMPARE(w_->renderView()->image()->hostFloat("A")[0], 0.8f);
}

void SpeedTest::frameTimeAndNodesThatRanAreShown() {
    // The first frame: everything ran.
    QVERIFY2(w_->frameText().contains("ran 2 of 2: read, colour"), qPrintable(w_->frameText()));
    QVERIFY(w_->scene()->nodeItem("read")->badgeRan());
    QVERIFY(w_->scene()->nodeItem("read")->badgeText().endsWith("ms"));
    w_->evaluation()->setPreviewBudget(0);
    QSlider* s = opacitySlider();
    s->setFocus();
    QTest::keyClick(s, Qt::Key_Home);
    QVERIFY(guitest::waitIdle(*w_));
    const QString text = w_->frameText();
    QVERIFY2(text.contains("colour: 256 × 128") && text.contains(" ms") && text.contains("ran 1 of 2: colour"),
             qPrintable(text));
    QVERIFY(w_->scene()->nodeItem("colour")->badgeRan());
    QVERIFY(!w_->scene()->nodeItem("read")->badgeRan());
    QVERIFY2(w_->scene()->nodeItem("read")->badgeText().endsWith("cached"),
             qPrintable(w_->scene()->nodeItem("read")->badgeText()));
    QVERIFY(guitest::screenshot(w_.get(), "speed-badges"));
}

QTEST_MAIN(SpeedTest)
#include "test_editor_speed.moc"
