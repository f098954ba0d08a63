// The explorer on a generated ensemble of 2,400 entries (tests/gui/
// ensemble.h): brushing on the parallel coordinates filters the image
// grid, several brushes combine, picking a picture or a polyline makes
// that row the one the render view shades (and the browser's sliders
// follow), the where-clause selects the same rows in `darkroom run
// --foreach ... --where`, the grid decodes only what is on screen, sorts by
// any column, shows the raw product or the pipeline's output, and the
// selection is saved with the pipeline and loads back.
#include "cinema_entries.h"
#include "cinema_panel.h"
#include "document.h"
#include "ensemble.h"
#include "explorer_panel.h"
#include "gui_support.h"
#include "image_grid.h"
#include "main_window.h"
#include "parallel_coords.h"
#include "polyline_raster.h"
#include "preview_graph.h"
#include "render_view.h"
#include "test_support.h"
#include "thumbnail_cache.h"
#include "thumbnail_sources.h"

#include <darkroom/data/cinema/database.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>

#include <QClipboard>
#include <QComboBox>
#include <QDir>
#include <QDirIterator>
#include <QFileInfo>
#include <QDockWidget>
#include <QLabel>
#include <QProcess>
#include <QScrollBar>
#include <QSlider>
#include <QToolButton>
#include <QtTest>

#include <memory>
#include <set>

using namespace darkroom;
using editor::MainWindow;

namespace {

constexpr std::size_t kRows = 2400;

// One database for every test, kept in the build folder between runs.
const std::string& ensemble() {
    static const std::string path = [] {
        const std::string p = DARKROOM_GUI_ARTIFACTS "/../gui-data/ensemble-2400.cdb";
        guitest::ensureEnsemble(p, kRows, 32);
        return p;
    }();
    return path;
}

// A drag with the left button held, as a hand makes it (QTest's mouseMove
// carries no buttons on every platform plugin).
void drag(QWidget* w, QPoint from, QPoint to, Qt::KeyboardModifiers mods = Qt::NoModifier, int steps = 6) {
    auto send = [&](QEvent::Type t, QPoint at, Qt::MouseButton b, Qt::MouseButtons held) {
        QMouseEvent e(t, at, w->mapToGlobal(at), b, held, mods);
        QApplication::sendEvent(w, &e);
    };
    send(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
    for (int i = 1; i <= steps; ++i) send(QEvent::MouseMove, from + (to - from) * i / steps, Qt::NoButton, Qt::LeftButton);
    send(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
}

std::set<std::size_t> rowsWhere(const std::function<bool(const guitest::EnsembleRow&)>& keep) {
    std::set<std::size_t> out;
    for (std::size_t i = 0; i < kRows; ++i)
        if (keep(guitest::ensembleRow(i))) out.insert(i);
    return out;
}

}  // namespace

class ExplorerTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void brushingFiltersTheGrid();
    void whereClauseSelectsTheBrushedRowsInTheRunner();
    void pickingAPictureShadesThatRow();
    void pickingAPolylineShadesThatRow();
    void gridDecodesOnlyWhatIsOnScreen();
    void gridSortsByAnyColumn();
    void gridShowsThePipelinesOutput();
    void selectionIsSavedWithThePipeline();
    void savedSelectionSurvivesTheLoadersRoundTrip();
    void polylinesAreRasterisedWithoutGapsOrOverlaps();
    void aDatabaseOpenedByARelativePathIsFoundByTheReader();
    void aDatabaseAnotherToolWroteIsExplored();

private:
    editor::ExplorerPanel* open();
    // Brushes axis `name` from value `low` to `high` (a few pixels beyond, so
    // both ends are inside).
    void brush(const char* name, double low, double high, Qt::KeyboardModifiers mods = Qt::NoModifier);
    std::set<std::size_t> gridItems() const;
    QString writePipeline(const char* name, const std::string& extra = {});
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
};

void ExplorerTest::initTestCase() {
    guitest::prepare();
    QVERIFY(guitest::registry().filter("CinemaReader"));
    QVERIFY(!ensemble().empty());
}

void ExplorerTest::init() {
    dir_ = std::make_unique<test::TempDir>();
    guitest::clearSettings();
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
}

void ExplorerTest::cleanup() {
    w_->document()->undoStack()->setClean();
    w_.reset();
    dir_.reset();
}

editor::ExplorerPanel* ExplorerTest::open() {
    if (!w_->openCinema(QString::fromStdString(ensemble()))) return nullptr;
    QTest::qWait(50);  // the dock's layout
    return w_->explorer();
}

void ExplorerTest::brush(const char* name, double low, double high, Qt::KeyboardModifiers mods) {
    editor::ParallelCoordinates* plot = w_->explorer()->plot();
    const int a = w_->explorer()->model().axisIndex(name);
    QVERIFY2(a >= 0, name);
    drag(plot, plot->pointOf(std::size_t(a), high) - QPoint(0, 3), plot->pointOf(std::size_t(a), low) + QPoint(0, 3), mods);
}

std::set<std::size_t> ExplorerTest::gridItems() const {
    const auto& order = w_->explorer()->model().order();
    return {order.begin(), order.end()};
}

QString ExplorerTest::writePipeline(const char* name, const std::string& extra) {
    const std::string text = "darkroom: 1\nnodes:\n  read:\n    type: CinemaReader\n    parameters:\n      database: " +
                             ensemble() + "\n" + extra +
                             "  colour:\n    type: ColorMapping\n    parameters:\n      channel: value\n"
                             "      colormap: inferno\n      range: manual\n      minimum: -1\n      maximum: 1\n"
                             "edges:\n  - read.image -> colour.image\n";
    test::writeText(dir_->file(name), text);
    return QString::fromStdString(dir_->file(name));
}

void ExplorerTest::brushingFiltersTheGrid() {
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    QVERIFY(w_->dock("explorer")->isVisible());
    QCOMPARE(ex->model().size(), kRows);
    QCOMPARE(ex->model().axes().size(), std::size_t(5));  // time, phi, model, frequency, amplitude
    QCOMPARE(gridItems().size(), kRows);

    brush("phi", 90, 180);
    auto expected = rowsWhere([](const auto& r) { return r.phi >= 90 && r.phi <= 180; });
    QCOMPARE(expected.size(), std::size_t(900));
    QCOMPARE(gridItems(), expected);
    QVERIFY2(ex->countLabel()->text().contains("900 of 2,400"), qPrintable(ex->countLabel()->text()));
    // What the grid shows is the selection.
    const auto visible = ex->grid()->visibleItems();
    QVERIFY(!visible.empty());
    for (std::size_t item : visible) QVERIFY(expected.count(item));

    // Another axis narrows (AND) ...
    brush("model", 0, 0);  // the first category: euler
    expected = rowsWhere([](const auto& r) { return r.phi >= 90 && r.phi <= 180 && r.model == "euler"; });
    QCOMPARE(gridItems(), expected);
    // ... a second range on the same axis widens (OR) ...
    brush("phi", 0, 0, Qt::ShiftModifier);
    expected = rowsWhere([](const auto& r) { return (r.phi == 0 || (r.phi >= 90 && r.phi <= 180)) && r.model == "euler"; });
    QCOMPARE(gridItems(), expected);
    QCOMPARE(ex->model().brushes().size(), std::size_t(3));
    QVERIFY(guitest::screenshot(w_.get(), "explorer-brushed"));
    // ... a plain drag replaces that axis' ranges, and a click on an axis clears it.
    brush("phi", 270, 315);
    expected = rowsWhere([](const auto& r) { return r.phi >= 270 && r.phi <= 315 && r.model == "euler"; });
    QCOMPARE(gridItems(), expected);
    const QPoint onModel = ex->plot()->pointOf(std::size_t(ex->model().axisIndex("model")), 1.5);
    drag(ex->plot(), onModel, onModel, Qt::NoModifier, 0);
    expected = rowsWhere([](const auto& r) { return r.phi >= 270 && r.phi <= 315; });
    QCOMPARE(gridItems(), expected);
}

void ExplorerTest::whereClauseSelectsTheBrushedRowsInTheRunner() {
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    brush("amplitude", 0.3, 0.42);
    brush("model", 1, 2);  // navier-stokes, lattice-boltzmann
    brush("time", 2, 3);
    const auto& b = ex->model().brushes();
    QCOMPARE(b.size(), std::size_t(3));
    const double lo = b[0].low, hi = b[0].high;
    const auto expected = rowsWhere([&](const auto& r) {
        return r.amplitude >= lo && r.amplitude <= hi && r.model != "euler" && r.time >= 2 && r.time <= 3;
    });
    QVERIFY(expected.size() > 10);
    QCOMPARE(gridItems(), expected);

    QGuiApplication::clipboard()->clear();
    ex->copyWhereClause();
    const QString clause = QGuiApplication::clipboard()->text();
    QVERIFY2(clause.contains("\"amplitude\" >= ") && clause.contains("\"model\" IN ('navier-stokes', 'lattice-boltzmann')"),
             qPrintable(clause));
    // The database's own query, which `--where` runs, selects the same rows.
    const auto db = CinemaDatabase::open(ensemble());
    QVERIFY(CinemaDatabase::looksLikeSql(clause.toStdString()));
    const auto rows = db.selectWhere(clause.toStdString());
    QCOMPARE(std::set<std::size_t>(rows.begin(), rows.end()), expected);

    // And the runner itself: one output per selected entry.
    const std::string pipeline = dir_->file("shade.yaml");
    test::writeText(pipeline, "darkroom: 1\nnodes:\n  read:\n    type: CinemaReader\n    parameters:\n      database: " +
                                  ensemble() + "\n  write:\n    type: ImageWriter\n    parameters:\n      path: out.exr\n"
                                  "edges:\n  - read.image -> write.image\n");
    QProcess run;
    run.start(QStringLiteral(DARKROOM_RUNNER_EXE),
              {"run", QString::fromStdString(pipeline), "--foreach", "read", "--where", clause, "--output",
               QString::fromStdString(dir_->file("out"))});
    QVERIFY(run.waitForFinished(120000));
    QVERIFY2(run.exitCode() == 0, run.readAllStandardError().constData());
    int written = 0;
    for (QDirIterator it(QString::fromStdString(dir_->file("out")), {"*.exr"}, QDir::Files, QDirIterator::Subdirectories);
         it.hasNext(); it.next())
        ++written;
    QCOMPARE(std::size_t(written), expected.size());
}

void ExplorerTest::pickingAPictureShadesThatRow() {
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    brush("phi", 135, 135);
    editor::ImageGrid* grid = ex->grid();
    const auto visible = grid->visibleItems();
    QVERIFY(visible.size() > 6);
    const std::size_t item = visible[5];
    QTest::mouseClick(grid->viewport(), Qt::LeftButton, {}, grid->cellRect(item).center());
    // The browser's entry, hence the reader, hence the render view.
    QCOMPARE(w_->cinema()->currentEntry(), item);
    const Node* reader = w_->document()->graph().node("cinemareader");
    QVERIFY(reader);
    QCOMPARE(reader->parameter("entry")->asInt(), std::int64_t(w_->cinema()->entries()[item].row));
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->image());
    QCOMPARE(w_->renderView()->image()->hostFloat("row")[0], float(ex->model().row(item)));
    // The sliders follow.
    const auto r = guitest::ensembleRow(ex->model().row(item));
    QCOMPARE(w_->cinema()->findChild<QLabel*>("value:time")->text(), QString::fromStdString(editor::shortestNumber(r.time)));
    QCOMPARE(w_->cinema()->findChild<QLabel*>("value:phi")->text(), QString("135"));
    QCOMPARE(grid->current(), std::optional<std::size_t>(item));
    // Keys move on: the next picture is shaded.
    grid->setFocus();
    QTest::keyClick(grid, Qt::Key_Right);
    QCOMPARE(w_->cinema()->currentEntry(), visible[6]);
    QVERIFY(guitest::waitIdle(*w_));
    QCOMPARE(w_->renderView()->image()->hostFloat("row")[0], float(ex->model().row(visible[6])));
    QVERIFY(guitest::screenshot(w_.get(), "explorer-picked"));
}

void ExplorerTest::pickingAPolylineShadesThatRow() {
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    // Four brushes leave one entry: time 4.5, phi 225, lattice-boltzmann, frequency 3.
    brush("time", 4.5, 4.5);
    brush("phi", 225, 225);
    brush("model", 2, 2);
    brush("frequency", 3, 3);
    const auto expected = rowsWhere(
        [](const auto& r) { return r.time == 4.5 && r.phi == 225 && r.model == "lattice-boltzmann" && r.frequency == 3; });
    QCOMPARE(expected.size(), std::size_t(1));
    QCOMPARE(gridItems(), expected);
    const std::size_t item = *expected.begin();
    // Halfway between the time and phi axes, on its polyline.
    editor::ParallelCoordinates* plot = ex->plot();
    const QPoint a = plot->pointOf(0, 4.5), b = plot->pointOf(1, 225);
    QTest::mouseClick(plot, Qt::LeftButton, {}, (a + b) / 2);
    QCOMPARE(w_->cinema()->currentEntry(), item);
    QVERIFY(guitest::waitIdle(*w_));
    QCOMPARE(w_->renderView()->image()->hostFloat("row")[0], float(item));
    QCOMPARE(qobject_cast<QSlider*>(w_->cinema()->control("phi"))->value(), 5);  // 225 is the sixth angle
    QVERIFY(guitest::screenshot(w_->dock("explorer"), "explorer-polyline"));
}

void ExplorerTest::gridDecodesOnlyWhatIsOnScreen() {
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    editor::ThumbnailCache* cache = ex->cache();
    editor::ImageGrid* grid = ex->grid();
    const std::size_t visible = grid->visibleItems().size();
    QVERIFY(visible > 0 && visible < kRows / 10);
    QVERIFY(QTest::qWaitFor([&] { return cache->idle() && cache->made() >= int(visible); }, 60000));
    // The screen and the next one (read ahead for scrolling), nothing more.
    QVERIFY2(cache->made() <= int(3 * visible), qPrintable(QString::number(cache->made())));
    for (std::size_t item : grid->visibleItems()) {
        bool fresh = false;
        QVERIFY(cache->find(item, &fresh) && fresh);
    }
    // Scrolled to the end, the last screen is made; most entries never were.
    grid->verticalScrollBar()->setValue(grid->verticalScrollBar()->maximum());
    QVERIFY(QTest::qWaitFor([&] {
        for (std::size_t item : grid->visibleItems())
            if (!cache->find(item)) return false;
        return true;
    }, 60000));
    QVERIFY(grid->visibleItems().back() == ex->model().order().back());
    QVERIFY2(cache->made() < int(kRows / 4), qPrintable(QString::number(cache->made())));
    QCOMPARE(cache->failed(), 0);
    QVERIFY(guitest::screenshot(w_->dock("explorer"), "explorer-grid-end"));
}

void ExplorerTest::gridSortsByAnyColumn() {
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    const int amplitude = ex->model().axisIndex("amplitude");
    ex->sortBox()->setCurrentIndex(amplitude + 1);  // after "database order"
    ex->findChild<QToolButton*>("descending")->setChecked(true);
    QVERIFY(ex->model().descending());
    const auto& order = ex->model().order();
    QCOMPARE(order.size(), kRows);
    for (std::size_t i = 1; i < order.size(); ++i)
        QVERIFY(ex->model().value(std::size_t(amplitude), order[i - 1]) >= ex->model().value(std::size_t(amplitude), order[i]));
    // The current entry stays in view in the new order; the top holds the largest.
    const auto current = ex->grid()->current();
    QVERIFY(current);
    QVERIFY(ex->grid()->viewport()->rect().contains(ex->grid()->cellRect(*current)));
    ex->grid()->verticalScrollBar()->setValue(0);
    QCOMPARE(ex->grid()->visibleItems().front(), std::size_t(order.front()));
    // Text columns sort by category (order of first appearance).
    const int model = ex->model().axisIndex("model");
    ex->sortBox()->setCurrentIndex(model + 1);
    ex->findChild<QToolButton*>("descending")->setChecked(false);
    QCOMPARE(guitest::ensembleRow(ex->model().row(order.front())).model, std::string("euler"));
    QCOMPARE(guitest::ensembleRow(ex->model().row(order.back())).model, std::string("lattice-boltzmann"));
    // Equal values keep database order.
    QVERIFY(order[0] < order[1] && order[1] < order[2]);
}

void ExplorerTest::gridShowsThePipelinesOutput() {
    QVERIFY(w_->openPipeline(writePipeline("p.yaml")));
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    QVERIFY(guitest::waitIdle(*w_));
    editor::ThumbnailCache* cache = ex->cache();
    QVERIFY(QTest::qWaitFor([&] { return cache->idle() && cache->made() > 0; }, 60000));
    const std::size_t item = ex->grid()->visibleItems().at(3);
    const QImage raw = *cache->find(item);
    // The pipeline's output: the entry through ColorMapping (inferno).
    ex->showBox()->setCurrentIndex(1);
    QVERIFY(ex->showsPipeline());
    QVERIFY(QTest::qWaitFor([&] {
        bool fresh = false;
        return cache->find(item, &fresh) && fresh && cache->idle();
    }, 60000));
    const QImage shaded = *cache->find(item);
    QVERIFY(shaded != raw);
    // Exactly what evaluating the pipeline for that entry gives.
    Graph g = w_->document()->graph();
    g.setParameter("read", "entry", Value(std::int64_t(w_->cinema()->entries()[item].row)));
    Evaluator ev;
    const QImage expected = editor::thumbnail(*ev.evaluateImage(g, "colour", "image"), cache->thumbnailSize());
    QCOMPARE(shaded, expected);
    QCOMPARE(cache->failed(), 0);
    QVERIFY(guitest::screenshot(w_.get(), "explorer-pipeline-output"));
    // And back to the products.
    ex->showBox()->setCurrentIndex(0);
    QVERIFY(QTest::qWaitFor([&] {
        bool fresh = false;
        return cache->find(item, &fresh) && fresh && cache->idle();
    }, 60000));
    QCOMPARE(*cache->find(item), raw);
}

void ExplorerTest::selectionIsSavedWithThePipeline() {
    QVERIFY(w_->openPipeline(writePipeline("p.yaml")));
    editor::ExplorerPanel* ex = open();
    QVERIFY(ex);
    brush("phi", 45, 90);
    const editor::ExplorerState first = ex->state();
    brush("model", 1, 1);
    ex->sortBox()->setCurrentIndex(ex->model().axisIndex("amplitude") + 1);
    const std::size_t selected = ex->model().selectedCount();
    const editor::ExplorerState state = ex->state();
    const std::size_t picked = ex->grid()->visibleItems().at(2);
    QTest::mouseClick(ex->grid()->viewport(), Qt::LeftButton, {}, ex->grid()->cellRect(picked).center());
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(!w_->document()->undoStack()->isClean());
    const QString saved = QString::fromStdString(dir_->file("saved.yaml"));
    QVERIFY(w_->savePipeline(saved));
    const std::string text = test::readText(saved.toStdString());
    QVERIFY2(text.find("explore: {brushes: [") != std::string::npos, text.c_str());

    // The runner loads it: the key is kept for the editor, nothing is wrong.
    Diagnostics d;
    const Graph loaded = loadPipeline(saved.toStdString(), guitest::registry(), d);
    QVERIFY2(!hasErrors(d), d.empty() ? "" : d.front().str().c_str());
    QVERIFY(!hasErrors(loaded.validate()));
    QProcess validate;
    validate.start(QStringLiteral(DARKROOM_RUNNER_EXE), {"validate", saved});
    QVERIFY(validate.waitForFinished(60000));
    QVERIFY2(validate.exitCode() == 0, validate.readAllStandardError().constData());

    // Undo goes back one gesture at a time (the sort, then the model brush).
    w_->document()->undoStack()->undo();  // the pick
    w_->document()->undoStack()->undo();  // the sort
    w_->document()->undoStack()->undo();  // the model brush
    QCOMPARE(ex->state(), first);
    QCOMPARE(ex->model().brushes().size(), std::size_t(1));

    // A new editor opening the saved pipeline has the same selection back.
    w_->document()->undoStack()->setClean();
    w_.reset();
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
    QVERIFY(w_->openPipeline(saved));
    ex = w_->explorer();
    QVERIFY(ex->hasDatabase());
    QVERIFY(w_->dock("explorer")->isVisible());
    QCOMPARE(ex->state(), state);
    QCOMPARE(ex->model().selectedCount(), selected);
    QCOMPARE(ex->model().sortAxis(), ex->model().axisIndex("amplitude"));
    QCOMPARE(ex->current(), std::optional<std::size_t>(picked));
    QCOMPARE(w_->cinema()->currentEntry(), picked);
    QVERIFY(!ex->grid()->cellRect(picked).isEmpty());
    QVERIFY(ex->grid()->viewport()->rect().contains(ex->grid()->cellRect(picked)));  // in view
    QVERIFY(w_->document()->undoStack()->isClean());  // opening changed nothing
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(guitest::screenshot(w_.get(), "explorer-reloaded"));
}

void ExplorerTest::savedSelectionSurvivesTheLoadersRoundTrip() {
    // Names and values a database may hold: spaces, commas, quotes,
    // backslashes, percent signs, text that reads as a number or a boolean.
    editor::ExplorerState s;
    s.brushes = {{"wind speed", "0.25", "1e-07"},
                 {"case \"a, b\"", "x, y", "back\\slash 100%"},
                 {"flag", "true", "1.5"}};
    s.sort = "wind speed";
    s.descending = true;
    s.pipeline = true;
    const std::string yaml = editor::toYaml(s);
    const std::string text = "darkroom: 1\nnodes:\n  read:\n    type: CinemaReader\n    explore: " + yaml + "\nedges: []\n";
    std::string current = text;
    // Loaded and saved twice, as the editor and the runner would.
    for (int round = 0; round < 2; ++round) {
        Diagnostics d;
        const Graph g = parsePipeline(current, "explore.yaml", guitest::registry(), d);
        QVERIFY2(!hasErrors(d), d.empty() ? "" : d.front().str().c_str());
        const Node* read = g.node("read");
        QVERIFY(read);
        QCOMPARE(editor::parseExplorerState(editor::explorerText(*read)), s);
        current = serializePipeline(g);
    }
}

void ExplorerTest::polylinesAreRasterisedWithoutGapsOrOverlaps() {
    // Three axes at columns 10, 60, 70 of a 80 x 100 image; two polylines:
    // a flat one at row 20, and a steep one from row 5 to row 95 and back.
    editor::PolylineRaster r(80, 100, {10, 60, 70});
    r.rasterise([](std::size_t gap, const editor::PolylineRaster::AddSegment& add) {
        add(20, 20, 0.0f);
        add(gap == 0 ? 5.0f : 95.0f, gap == 0 ? 95.0f : 5.0f, 1.0f);
    }, 2);
    const QImage img = r.toImage(0.01f, true, 0, 255);  // one line: opaque
    auto alpha = [&](int x, int y) { return qAlpha(img.pixel(x, y)); };
    // The flat line covers every column from the first axis to the last, once.
    for (int x = 0; x < 80; ++x) QCOMPARE(alpha(x, 20) > 0, x >= 10 && x <= 70);
    // The steep one has a pixel in every row it crosses, in each gap.
    for (int y = 6; y < 95; ++y) {
        if (y == 20) continue;  // the flat line's row
        int first = 0, second = 0;
        for (int x = 10; x < 60; ++x) first += alpha(x, y) > 0;
        for (int x = 60; x <= 70; ++x) second += alpha(x, y) > 0;
        QVERIFY2(first >= 1 && second >= 1, qPrintable(QStringLiteral("row %1: %2, %3").arg(y).arg(first).arg(second)));
    }
    // Counted once on the axis between two gaps (opacity grows with the count).
    const QImage faint = r.toImage(10.0f, true, 0, 255);
    QCOMPARE(qAlpha(faint.pixel(60, 20)), qAlpha(faint.pixel(30, 20)));
    QVERIFY(qAlpha(faint.pixel(30, 20)) > 0);
    // Colour by value: the flat line (0) and the steep one (1) differ.
    QVERIFY(img.pixel(12, 20) != img.pixel(10, 5));
    // The order of the lines does not matter.
    editor::PolylineRaster swapped(80, 100, {10, 60, 70});
    swapped.rasterise([](std::size_t gap, const editor::PolylineRaster::AddSegment& add) {
        add(gap == 0 ? 5.0f : 95.0f, gap == 0 ? 95.0f : 5.0f, 1.0f);
        add(20, 20, 0.0f);
    }, 1);
    QCOMPARE(swapped.toImage(0.01f, true, 0, 255), img);
}

void ExplorerTest::aDatabaseOpenedByARelativePathIsFoundByTheReader() {
    // The pipeline in one folder, the database named relative to the
    // working folder (as on a command line): the reader must still find it.
    QDir().mkpath(QString::fromStdString(dir_->file("pipelines")));
    test::writeText(dir_->file("pipelines/p.yaml"), "darkroom: 1\nnodes:\n  read:\n    type: CinemaReader\nedges: []\n");
    QVERIFY(w_->openPipeline(QString::fromStdString(dir_->file("pipelines/p.yaml"))));
    const QString before = QDir::currentPath();
    QVERIFY(QDir::setCurrent(QFileInfo(QString::fromStdString(ensemble())).absolutePath()));
    const bool opened = w_->openCinema(QFileInfo(QString::fromStdString(ensemble())).fileName());
    QDir::setCurrent(before);
    QVERIFY(opened);
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY2(w_->renderView()->message().isEmpty(), qPrintable(w_->renderView()->message()));
    QVERIFY(w_->renderView()->image());
    QCOMPARE(w_->renderView()->image()->hostFloat("row")[0], 0.0f);
    QVERIFY(w_->explorer()->hasDatabase());
}

QTEST_MAIN(ExplorerTest)
#include "test_editor_explorer.moc"

// cinemasci's test database (../shared/data): theta and phi, two FILE
// columns of PNG pictures. Brushing phi keeps the rows the CSV says; a
// picked picture is shaded in the render view.
void ExplorerTest::aDatabaseAnotherToolWroteIsExplored() {
    const std::string cdb = test::sharedData("cinema/multiple_artifacts.cdb");
    if (cdb.empty()) QSKIP("../shared/data is absent");
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    QTest::qWait(50);
    editor::ExplorerPanel* ex = w_->explorer();
    QVERIFY(ex);
    QCOMPARE(ex->model().size(), std::size_t(20));
    QVERIFY(ex->model().axisIndex("theta") >= 0);
    QVERIFY(ex->model().axisIndex("phi") >= 0);
    brush("phi", -90, 90);
    std::set<std::size_t> expected;
    for (std::size_t item = 0; item < ex->model().size(); ++item) {
        const double phi = -180 + 18.0 * double(ex->model().row(item));  // the CSV's rows: phi from -180 by 18
        if (phi >= -90 && phi <= 90) expected.insert(item);
    }
    QCOMPARE(expected.size(), std::size_t(11));
    QCOMPARE(gridItems(), expected);
    editor::ImageGrid* grid = ex->grid();
    const auto visible = grid->visibleItems();
    QVERIFY(visible.size() > 2);
    QTest::mouseClick(grid->viewport(), Qt::LeftButton, {}, grid->cellRect(visible[2]).center());
    QCOMPARE(w_->cinema()->currentEntry(), visible[2]);
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->image());
    // Every picture on screen decoded (the thumbnails of PNGs another tool wrote).
    editor::ThumbnailCache* cache = ex->cache();
    QVERIFY(QTest::qWaitFor([&] {
        for (std::size_t item : grid->visibleItems())
            if (!cache->find(item)) return false;
        return cache->idle();
    }, 60000));
    QCOMPARE(cache->failed(), 0);
    QTest::qWait(100);  // the grid's repaint of what landed
    QVERIFY(guitest::screenshot(w_.get(), "explorer-shared-data"));
}
