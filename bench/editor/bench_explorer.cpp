// The explorer's interactive figures on a generated ensemble of 10,000
// entries (tests/gui/ensemble.h, 32 x 32 products), in the editor window
// as a user has it (the render view, the graph, the Cinema browser and the
// explorer docks), under Xvfb with Mesa llvmpipe:
//
//  - brushing: a drag along an axis, a mouse move every --interval ms; for
//    each move, the time from the event to the end of the paint of both
//    the parallel coordinates and the grid (the window's backing store is
//    flushed to the X server inside that paint cycle). Three gestures: a
//    new brush growing over the amplitude axis (the selection changes at
//    every move), the brush moved along it, and a brush on the time axis
//    while the amplitude brush stays (two axes combined).
//  - scrolling the grid of all 10,000 entries: once page by page, waiting
//    at each page until its cells are decoded (decode throughput); then
//    wheel notches of one row every --interval ms from the top to the end,
//    each frame timed from the wheel event to the end of the grid's paint.
//
// A benchmark, not a test: it prints its figures and asserts nothing.
#include "ensemble.h"

#include "cinema_entries.h"
#include "cinema_panel.h"
#include "document.h"
#include "evaluation.h"
#include "explorer_state.h"
#include "explorer_panel.h"
#include "image_grid.h"
#include "main_window.h"
#include "parallel_coords.h"
#include "thumbnail_cache.h"

#include <darkroom/core/registry.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QDockWidget>
#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QScreen>
#include <QScrollBar>
#include <QStandardPaths>
#include <QTest>
#include <QWheelEvent>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <vector>

namespace {

struct Options {
    QString work;
    int rows = 10000;
    int size = 32;
    int moves = 60;
    int interval = 16;
};

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return -1;
    std::sort(v.begin(), v.end());
    const double i = p * double(v.size() - 1);
    const std::size_t lo = std::size_t(i);
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (v[hi] - v[lo]) * (i - double(lo));
}

int fail(const QString& m) {
    std::fprintf(stderr, "bench_explorer: %s\n", qPrintable(m));
    return 1;
}

// Sends `event` to `target` and runs the event loop until every widget in
// `painted` has painted again (or 2 s pass); the milliseconds it took.
double timed(const std::function<void()>& event, const std::vector<std::function<int()>>& painted) {
    std::vector<int> before;
    for (const auto& p : painted) before.push_back(p());
    QElapsedTimer t;
    t.start();
    event();
    auto done = [&] {
        for (std::size_t i = 0; i < painted.size(); ++i)
            if (painted[i]() == before[i]) return false;
        return true;
    };
    while (!done() && t.elapsed() < 2000) QCoreApplication::processEvents(QEventLoop::AllEvents, 1);
    return double(t.nsecsElapsed()) / 1e6;
}

struct Gesture {
    QString label;
    std::vector<double> ms;    // per move: event to both widgets painted
    std::vector<double> draw;  // per move: drawing the selected polylines
    std::vector<double> selected;
};

class Bench {
public:
    Bench(editor::MainWindow& w, const Options& o) : w_(w), o_(o), ex_(w.explorer()) {}

    void mouse(QEvent::Type type, QPoint at, Qt::MouseButton b, Qt::MouseButtons held) {
        QWidget* plot = ex_->plot();
        QMouseEvent e(type, at, plot->mapToGlobal(at), b, held, Qt::NoModifier);
        QApplication::sendEvent(plot, &e);
    }

    // Press at `from`, `o_.moves` moves to `to`, release; each move timed.
    Gesture drag(const QString& label, QPoint from, QPoint to) {
        Gesture g{label, {}, {}, {}};
        editor::ParallelCoordinates* plot = ex_->plot();
        mouse(QEvent::MouseButtonPress, from, Qt::LeftButton, Qt::LeftButton);
        QTest::qWait(o_.interval);
        for (int i = 1; i <= o_.moves; ++i) {
            const QPoint at = from + (to - from) * i / o_.moves;
            g.ms.push_back(timed([&] { mouse(QEvent::MouseMove, at, Qt::NoButton, Qt::LeftButton); },
                                 {[plot] { return plot->paints(); }, [this] { return ex_->grid()->paints(); }}));
            g.draw.push_back(plot->lastSelectionMs());
            g.selected.push_back(double(ex_->model().selectedCount()));
            QTest::qWait(o_.interval);
        }
        mouse(QEvent::MouseButtonRelease, to, Qt::LeftButton, Qt::NoButton);
        QTest::qWait(100);
        return g;
    }

    std::vector<Gesture> brushing() {
        editor::ParallelCoordinates* plot = ex_->plot();
        const auto amplitude = std::size_t(ex_->model().axisIndex("amplitude"));
        const auto time = std::size_t(ex_->model().axisIndex("time"));
        std::vector<Gesture> out;
        // A new brush from the top of the amplitude axis down to its middle.
        out.push_back(drag("new brush growing on amplitude", plot->pointOf(amplitude, 1.0),
                           plot->pointOf(amplitude, 0.55)));
        // Moved down along the axis, by its middle.
        out.push_back(drag("brush moved along amplitude", plot->pointOf(amplitude, 0.78),
                           plot->pointOf(amplitude, 0.35)));
        // A second axis: time, while the amplitude brush stays.
        out.push_back(drag("brush on time, amplitude brushed", plot->pointOf(time, 0.0), plot->pointOf(time, 9.5)));
        return out;
    }

    bool visibleDecoded() {
        for (std::size_t item : ex_->grid()->visibleItems()) {
            bool fresh = false;
            if (!ex_->cache()->find(item, &fresh) || !fresh) return false;
        }
        return true;
    }

    // Page by page to the end, each page's cells decoded: thumbnails per second.
    double decodeOnce(int* pages) {
        QScrollBar* sb = ex_->grid()->verticalScrollBar();
        sb->setValue(0);
        const int made0 = ex_->cache()->made();
        QElapsedTimer t;
        t.start();
        *pages = 0;
        for (;;) {
            while (!visibleDecoded() && t.elapsed() < 600000) QTest::qWait(2);
            ++*pages;
            if (sb->value() >= sb->maximum()) break;
            sb->setValue(sb->value() + sb->pageStep());
            QCoreApplication::processEvents();
        }
        return (ex_->cache()->made() - made0) / std::max(1e-3, t.elapsed() / 1000.0);
    }

    // One wheel notch (one row) every interval: down from the top to the
    // end (rows: 0 = all), or up for `rows` rows.
    std::vector<double> scroll(bool down, int rows, int* decodedOnTheWay) {
        editor::ImageGrid* grid = ex_->grid();
        QScrollBar* sb = grid->verticalScrollBar();
        if (down) sb->setValue(0);
        QTest::qWait(200);
        const int made0 = ex_->cache()->made();
        std::vector<double> ms;
        QWidget* vp = grid->viewport();
        const QPoint at = vp->rect().center();
        while ((down ? sb->value() < sb->maximum() : sb->value() > 0) && (rows == 0 || int(ms.size()) < rows)) {
            ms.push_back(timed([&] {
                QWheelEvent e(at, vp->mapToGlobal(at), QPoint(), QPoint(0, down ? -120 : 120), Qt::NoButton,
                              Qt::NoModifier, Qt::NoScrollPhase, false);
                QApplication::sendEvent(vp, &e);
            }, {[grid] { return grid->paints(); }}));
            QTest::qWait(o_.interval);
        }
        *decodedOnTheWay = ex_->cache()->made() - made0;
        return ms;
    }

private:
    editor::MainWindow& w_;
    const Options& o_;
    editor::ExplorerPanel* ex_;
};

// docs/editor.md's picture: a pipeline shading the entries (ColorMapping,
// cool-to-warm), two axes brushed, the grid sorted by amplitude and showing
// the pipeline's output, its first entry picked and in the render view.
int picture(editor::MainWindow& w, const QString& cdb, const Options& o, const QString& file) {
    const QString yaml = o.work + "/explorer-picture.yaml";
    QFile f(yaml);
    if (!f.open(QIODevice::WriteOnly)) return fail("cannot write " + yaml);
    f.write(QStringLiteral("darkroom: 1\nnodes:\n  read:\n    type: CinemaReader\n    parameters:\n"
                           "      database: %1\n  colour:\n    type: ColorMapping\n    parameters:\n"
                           "      channel: value\n      colormap: cool-to-warm\n      range: manual\n"
                           "      minimum: -1\n      maximum: 1\nedges:\n  - read.image -> colour.image\n")
                .arg(QFileInfo(cdb).absoluteFilePath())
                .toUtf8());
    f.close();
    if (!w.openPipeline(yaml) || !w.openCinema(cdb)) return fail("cannot open the pipeline or the database");
    w.resizeDocks({w.dock("explorer")}, {w.height() * 46 / 100}, Qt::Vertical);
    QTest::qWait(300);
    editor::ExplorerPanel* ex = w.explorer();
    QTest::qWait(600);  // the explorer takes the pipeline once the graph rests
    editor::ExplorerState s;
    s.brushes = {{"phi", "90", "180"}, {"amplitude", "0.55", "1"}};
    s.sort = "amplitude";
    s.descending = true;
    s.pipeline = true;
    ex->setState(s);
    w.cinema()->selectEntry(ex->model().order().front());
    QElapsedTimer t;
    t.start();
    while (t.elapsed() < 60000 && !(ex->cache()->idle() && !w.evaluation()->busy())) QTest::qWait(50);
    QTest::qWait(500);
    w.document()->undoStack()->setClean();
    // What the X server shows: grab() leaves out what is drawn over the
    // OpenGL render view.
    const QPixmap shot = w.screen()->grabWindow(w.winId());
    if (shot.isNull() || !shot.save(file)) return fail("cannot write " + file);
    std::printf("wrote %s\n", qPrintable(file));
    return 0;
}

// Where opening goes: the parts the browser and the explorer share.
void printOpenParts(const QString& cdb) {
    QElapsedTimer t;
    t.start();
    const auto db = darkroom::CinemaDatabase::open(cdb.toStdString());
    const double read = t.nsecsElapsed() / 1e6;
    t.restart();
    const auto entries = editor::cinemaEntries(db);
    const double list = t.nsecsElapsed() / 1e6;
    t.restart();
    const editor::ExplorerModel model(db, entries);
    const double table = t.nsecsElapsed() / 1e6;
    t.restart();
    (void)db.describe();
    std::fprintf(stderr, "open parts: data.csv %.0f ms, entries %.0f ms, explorer table %.0f ms, describe %.0f ms\n", read,
                 list, table, t.nsecsElapsed() / 1e6);
}

// The three gestures, then the frame with nothing to compute; every move's time.
std::vector<double> reportBrushing(Bench& bench, editor::ExplorerPanel* ex, const Options& o) {
    std::printf("## Brushing: mouse move to plot and grid painted\n\n");
    std::printf("| gesture | moves | selected rows (min–max) | median ms | p90 ms | max ms | polylines drawn median ms |\n");
    std::printf("|---|---|---|---|---|---|---|\n");
    std::vector<double> all;
    for (const auto& g : bench.brushing()) {
        std::printf("| %s | %zu | %.0f–%.0f | %.1f | %.1f | %.1f | %.1f |\n", qPrintable(g.label), g.ms.size(),
                    *std::min_element(g.selected.begin(), g.selected.end()),
                    *std::max_element(g.selected.begin(), g.selected.end()), percentile(g.ms, 0.5), percentile(g.ms, 0.9),
                    percentile(g.ms, 1.0), percentile(g.draw, 0.5));
        all.insert(all.end(), g.ms.begin(), g.ms.end());
        std::fflush(stdout);
    }
    std::printf("| **all moves** | %zu | | **%.1f** | %.1f | %.1f | |\n\n", all.size(), percentile(all, 0.5),
                percentile(all, 0.9), percentile(all, 1.0));
    {
        // The floor under every figure: one frame of the window, the plot
        // repainted from its cached layers and flushed by the raster
        // backing store (the render view is a native window of its own,
        // render_surface.h: it is not composed with the rest).
        std::vector<double> floor;
        editor::ParallelCoordinates* plot = ex->plot();
        for (int i = 0; i < 30; ++i) {
            floor.push_back(timed([plot] { plot->update(); }, {[plot] { return plot->paints(); }}));
            QTest::qWait(o.interval);
        }
        std::printf("a frame with nothing to compute (the plot repainted from its cached layers): median %.1f ms, max %.1f ms\n\n",
                    percentile(floor, 0.5), percentile(floor, 1.0));
    }

    return all;
}

// Decoded once page by page, then wheel down over all entries: the cache
// holds a quarter, so the rest is made again on the way; then back up over
// the rows still cached.
void reportScrolling(Bench& bench, editor::ExplorerPanel* ex, const Options& o, std::vector<double>* frames,
                     std::vector<double>* up) {
    // The grid of every entry.
    ex->model().setBrushes({});
    ex->plot()->selectionChanged();
    ex->grid()->modelChanged();
    QTest::qWait(100);
    int pages = 0;
    const double rate = bench.decodeOnce(&pages);
    int remade = 0, remadeUp = 0;
    *frames = bench.scroll(true, 0, &remade);
    const int cachedRows = int(ex->cache()->count() / std::size_t(ex->grid()->columns())) -
                           2 * int(ex->grid()->visibleItems().size() / std::size_t(ex->grid()->columns()));
    *up = bench.scroll(false, std::max(1, cachedRows), &remadeUp);
    std::printf("## Scrolling the grid of %d entries\n\n", o.rows);
    std::printf("decoded once, page by page: %d pages, %.0f thumbnails/s; cache %zu thumbnails, %.0f MiB\n\n", pages, rate,
                ex->cache()->count(), ex->cache()->bytes() / 1048576.0);
    std::printf("| pass | frames | thumbnails made on the way | median ms | p99 ms | max ms | frames over 100 ms |\n"
                "|---|---|---|---|---|---|---|\n");
    auto row = [](const char* what, const std::vector<double>& f, int made) {
        std::printf("| %s | %zu | %d | %.1f | %.1f | %.1f | %ld |\n", what, f.size(), made, percentile(f, 0.5),
                    percentile(f, 0.99), percentile(f, 1.0),
                    long(std::count_if(f.begin(), f.end(), [](double x) { return x > 100; })));
    };
    row("wheel down, one row per notch, top to end", *frames, remade);
    row("wheel up over the rows still cached", *up, remadeUp);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QStandardPaths::setTestModeEnabled(true);  // settings and autosaves out of the user's
    QCommandLineParser cli;
    cli.addHelpOption();
    cli.addOption({"work", "Folder for the generated database", "DIR", "bench-editor"});
    cli.addOption({"rows", "Entries in the database", "N", "10000"});
    cli.addOption({"size", "Products' width and height in pixels", "PX", "32"});
    cli.addOption({"moves", "Mouse moves per brush gesture", "N", "60"});
    cli.addOption({"interval", "Milliseconds between moves and wheel notches", "MS", "16"});
    cli.addOption({"screenshot", "Write docs/editor.md's picture of the explorer to FILE and stop", "FILE"});
    cli.process(app);
    Options o;
    o.work = cli.value("work");
    o.rows = cli.value("rows").toInt();
    o.size = cli.value("size").toInt();
    o.moves = cli.value("moves").toInt();
    o.interval = cli.value("interval").toInt();

    const QString cdb = o.work + QStringLiteral("/explorer-%1-%2px.cdb").arg(o.rows).arg(o.size);
    QElapsedTimer gen;
    gen.start();
    QDir().mkpath(o.work);
    guitest::ensureEnsemble(cdb.toStdString(), std::size_t(o.rows), o.size);
    std::fprintf(stderr, "database ready in %.1f s: %s\n", gen.elapsed() / 1000.0, qPrintable(cdb));

    printOpenParts(cdb);
    darkroom::Registry registry;
    const auto problems = registry.loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
    editor::MainWindow w(registry, problems);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) return fail("the window was not exposed");
    if (cli.isSet("screenshot")) return picture(w, cdb, o, cli.value("screenshot"));
    QElapsedTimer open;
    open.start();
    if (!w.openCinema(cdb)) return fail("cannot open " + cdb);
    const double openMs = open.elapsed();
    QTest::qWait(500);
    Bench bench(w, o);
    editor::ExplorerPanel* ex = w.explorer();

    std::printf("# darkroom-editor explorer, %d entries (%d x %d products), window %d x %d\n\n", o.rows, o.size, o.size,
                w.width(), w.height());
    std::printf("opened (data.csv, entries, plot) in %.0f ms; plot %d x %d, grid %d x %d (%d columns, %zu cells visible)\n\n",
                openMs, ex->plot()->width(), ex->plot()->height(), ex->grid()->viewport()->width(),
                ex->grid()->viewport()->height(), ex->grid()->columns(), ex->grid()->visibleItems().size());

    const std::vector<double> all = reportBrushing(bench, ex, o);

    std::vector<double> frames, up;
    reportScrolling(bench, ex, o, &frames, &up);
    std::printf("RESULT brushing_median_ms=%.1f brushing_max_ms=%.1f scroll_max_frame_ms=%.1f scroll_median_frame_ms=%.1f "
                "scroll_cached_max_frame_ms=%.1f\n",
                percentile(all, 0.5), percentile(all, 1.0), percentile(frames, 1.0), percentile(frames, 0.5),
                percentile(up, 1.0));
    w.document()->undoStack()->setClean();
    return 0;
}
