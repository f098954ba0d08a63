// The editor's interactive figure: how long from a drag event on a value to
// new pixels on screen, and from the end of the drag to the settled frame
// at full resolution, on the demo pipeline (docs/examples/demo.yaml) with
// the demo scene captured at 1024 x 1024 (--size: 2048, 2048x1024, ...).
//
// Driven with QTest mouse events through the graph view, as a hand drags a
// number field (press, moves every --interval ms, release). "New pixels on
// screen" is the render view's frameSwapped after it drew the first frame
// that includes the event's value (a frame of a later edit includes it too).
// A benchmark, not a test: it prints its figures and asserts nothing.
#include "document.h"
#include "evaluation.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "main_window.h"
#include "node_item.h"
#include "param_widget.h"
#include "render_view.h"

#include <darkroom/core/evaluator.h>
#include <darkroom/core/pipeline.h>
#include <darkroom/core/registry.h>

#include <QApplication>
#include <QCommandLineParser>
#include <QDir>
#include <QDoubleSpinBox>
#include <QElapsedTimer>
#include <QFile>
#include <QGraphicsProxyWidget>
#include <QLineEdit>
#include <QProcess>
#include <QScreen>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTest>

#include <algorithm>
#include <cstdio>
#include <vector>

namespace {

struct Options {
    QString work;
    int width = 1024, height = 1024;
    int steps = 40;
    int interval = 16;  // ms between moves: a 60 Hz hand
    int pixelsPerStep = 3;
    int drags = 3;      // per value; the first (right after opening) is reported apart
};

struct Frame {
    double ms;
    std::uint64_t generation;
    int level;
};

struct DragResult {
    std::vector<double> latencies;  // ms, one per event that changed the value
    int frames = 0;                 // frames presented during the drag
    std::vector<int> levels;        // preview levels shown
    std::vector<double> previewCompute;  // ms of evaluation per preview frame
    double settleMs = -1;           // release -> full-resolution frame on screen
    double settleCompute = -1;      // ms of the settling evaluation itself
    std::vector<double> paint;      // ms from a result's arrival on the UI thread to the swap
    std::vector<double> handling;   // ms the UI thread spent delivering each move (edit, graph update)
    editor::FrameProfile profile;   // of the last preview frame
};

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return -1;
    std::sort(v.begin(), v.end());
    const double i = p * double(v.size() - 1);
    const std::size_t lo = std::size_t(i);
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (v[hi] - v[lo]) * (i - double(lo));
}

bool fail(const QString& m) {
    std::fprintf(stderr, "bench_editor: %s\n", qPrintable(m));
    return false;
}

// Each size has its folder under --work: the captured scenes (out/demo/)
// and the pipeline copy (pipelines/demo/demo.yaml, which reads ../../out/demo).
QString sizeFolder(const Options& o) { return o.work + QStringLiteral("/demo-%1x%2").arg(o.width).arg(o.height); }

// The three demo scene files at width x height, one camera (phi 45, theta
// 40, the view demo.yaml reads), captured with the runner as scripts/demo.sh
// does.
bool captureDemo(const Options& o) {
    const QString root = sizeFolder(o);
    const QString out = root + "/out/demo";
    const QString stamp = out + "/captured";
    if (QFile::exists(stamp)) return true;
    QDir().mkpath(out);
    QDir().mkpath(root + "/scenes");
    for (const char* part : {"surface", "flow", "particles"}) {
        QFile in(QStringLiteral(DARKROOM_SOURCE_DIR "/docs/examples/demo/%1.yaml").arg(part));
        if (!in.open(QIODevice::ReadOnly)) return fail("cannot read " + in.fileName());
        QString text = QString::fromUtf8(in.readAll());
        const QString size = QStringLiteral("resolution: [%1, %2]").arg(o.width).arg(o.height);
        for (const auto& [from, to] : {std::pair<QString, QString>{"resolution: [768, 768]", size},
                                       {"phi: [0, 45, 90, 135, 180, 225, 270, 315]", "phi: [45]"},
                                       {"theta: [15, 40]", "theta: [40]"}}) {
            if (!text.contains(from)) return fail(in.fileName() + " no longer holds '" + from + "'; update the benchmark");
            text.replace(from, to);
        }
        const QString scene = root + "/scenes/" + part + ".yaml";
        QFile f(scene);
        if (!f.open(QIODevice::WriteOnly) || f.write(text.toUtf8()) < 0) return fail("cannot write " + scene);
        f.close();
        QProcess p;
        p.setProcessChannelMode(QProcess::ForwardedErrorChannel);
        p.start(DARKROOM_RUNNER, {"--quiet", "capture", scene, "--output", out + "/" + part + ".cdb", "--overwrite"});
        if (!p.waitForFinished(600000) || p.exitCode() != 0) return fail(QStringLiteral("capture of %1 failed").arg(part));
    }
    QFile s(stamp);
    return s.open(QIODevice::WriteOnly) || fail("cannot write " + stamp);
}

class Bench {
public:
    Bench(editor::MainWindow& w, const Options& o) : w_(w), o_(o) {
        QObject::connect(&w_, &editor::MainWindow::framePresented, [this](std::uint64_t g, int level) {
            frames_.push_back({clock_.nsecsElapsed() / 1e6, g, level});
        });
        QObject::connect(w_.evaluation(), &editor::Evaluation::finished, [this](const editor::EvalResult& r) {
            if (r.level > 0) lastPreview_ = r.profile;
            else lastFull_ = r.profile;
            computed_.push_back({r.generation, r.level, r.profile.seconds * 1000.0, clock_.nsecsElapsed() / 1e6});
        });
        clock_.start();
    }

    // Waits until the frame of the latest edit is on screen at full resolution.
    bool waitSettled(std::uint64_t generation, double* atMs = nullptr) {
        QElapsedTimer t;
        t.start();
        while (t.elapsed() < 120000) {
            for (const auto& f : frames_)
                if (f.generation >= generation && f.level == 0) {
                    if (atMs) *atMs = f.ms;
                    return true;
                }
            QTest::qWait(2);
        }
        return fail("no full-resolution frame within 120 s");
    }

    // The number field of node.port in viewport coordinates, scrolled into view.
    QPoint fieldPos(const QString& node, const QString& port, QLineEdit** edit) {
        editor::NodeItem* item = w_.scene()->nodeItem(node);
        editor::ParamWidget* pw = item ? item->paramWidget(port) : nullptr;
        *edit = pw && pw->spinBox() ? pw->spinBox()->findChild<QLineEdit*>() : nullptr;
        if (!*edit) return {};
        QGraphicsProxyWidget* proxy = pw->graphicsProxyWidget();
        if (!proxy) proxy = pw->window()->graphicsProxyWidget();
        if (!proxy) return {};
        w_.graphView()->centerOn(proxy);
        QCoreApplication::processEvents();
        const QPoint inProxy = (*edit)->mapTo(pw->window(), (*edit)->rect().center());
        return w_.graphView()->mapFromScene(proxy->mapToScene(QPointF(inProxy)));
    }

    bool drag(const QString& node, const QString& port, int direction, DragResult* out) {
        QLineEdit* edit = nullptr;
        QPoint p = fieldPos(node, port, &edit);
        if (!edit) return fail("no number field for " + node + "." + port);
        QWidget* vp = w_.graphView()->viewport();
        frames_.clear();
        computed_.clear();
        QTest::mousePress(vp, Qt::LeftButton, {}, p);
        QTest::qWait(o_.interval);
        struct Event {
            double ms;
            std::uint64_t generation;
        };
        std::vector<Event> events;
        std::uint64_t last = w_.evaluation()->generation();
        for (int i = 0; i < o_.steps; ++i) {
            p.rx() += direction * o_.pixelsPerStep;
            const double t = clock_.nsecsElapsed() / 1e6;
            QTest::mouseMove(vp, p);
            out->handling.push_back(clock_.nsecsElapsed() / 1e6 - t);
            const std::uint64_t g = w_.evaluation()->generation();
            if (g != last) events.push_back({t, g});  // this event asked for new pixels
            last = g;
            QTest::qWait(o_.interval);
        }
        const double release = clock_.nsecsElapsed() / 1e6;
        QTest::mouseRelease(vp, Qt::LeftButton, {}, p);
        double settledAt = -1;
        if (events.empty()) return fail("dragging " + node + "." + port + " changed nothing");
        if (!waitSettled(events.back().generation, &settledAt)) return false;
        out->settleMs = settledAt - release;
        for (const auto& e : events)
            for (const auto& f : frames_)
                if (f.generation >= e.generation && f.ms >= e.ms) {
                    out->latencies.push_back(f.ms - e.ms);
                    break;
                }
        for (const auto& f : frames_)
            if (f.ms <= release) {
                ++out->frames;
                if (f.level > 0) out->levels.push_back(f.level);
            }
        for (const auto& c : computed_) {
            for (const auto& f : frames_)
                if (f.generation == c.generation && f.level == c.level) out->paint.push_back(f.ms - c.deliveredAt);
            if (c.level > 0) out->previewCompute.push_back(c.ms);
            else if (c.generation == events.back().generation) out->settleCompute = c.ms;
        }
        return true;
    }

    // One edit without preview (the budget set to 0): the full-resolution
    // evaluation that every drag step would cost without previews.
    bool fullFrame(const QString& node, const QString& port, double value, double* inputToPixels, double* compute) {
        const double budget = w_.evaluation()->previewBudget();
        w_.evaluation()->setPreviewBudget(0);
        frames_.clear();
        computed_.clear();
        const double t = clock_.nsecsElapsed() / 1e6;
        w_.document()->edit("bench", [&](darkroom::Graph& g) {
            g.setParameter(node.toStdString(), port.toStdString(), darkroom::Value(value));
        });
        const std::uint64_t g = w_.evaluation()->generation();
        double at = -1;
        const bool ok = waitSettled(g, &at);
        w_.evaluation()->setPreviewBudget(budget);
        *inputToPixels = at - t;
        *compute = -1;
        for (const auto& c : computed_)
            if (c.generation == g) *compute = c.ms;
        return ok;
    }

private:
    struct Computed {
        std::uint64_t generation;
        int level;
        double ms;
        double deliveredAt;
    };
    editor::MainWindow& w_;
    const Options& o_;
    QElapsedTimer clock_;
    std::vector<Frame> frames_;
    std::vector<Computed> computed_;

public:
    editor::FrameProfile lastPreview_, lastFull_;
};

QString levelsText(const std::vector<int>& levels) {
    if (levels.empty()) return "none";
    const auto [lo, hi] = std::minmax_element(levels.begin(), levels.end());
    return *lo == *hi ? QStringLiteral("1/%1").arg(1 << *lo) : QStringLiteral("1/%1–1/%2").arg(1 << *lo).arg(1 << *hi);
}

}  // namespace

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("darkroom-bench");  // never the user's saved layout
    QStandardPaths::setTestModeEnabled(true);
    QCommandLineParser cli;
    cli.setApplicationDescription("Input-to-pixels benchmark of darkroom-editor on the demo pipeline");
    cli.addHelpOption();
    cli.addOption({"work", "Folder for the captured demo and the pipeline copy", "DIR", "bench-editor"});
    cli.addOption({"size", "Capture resolution: PX (square) or WxH", "PX", "1024"});
    cli.addOption({"steps", "Mouse moves per drag", "N", "40"});
    cli.addOption({"interval", "Milliseconds between moves", "MS", "16"});
    cli.addOption({"drags", "Drags per value (the first, right after opening, is reported apart)", "N", "3"});
    cli.addOption({"screenshot", "Only save a screenshot of the editor on the demo (the README's picture) and exit",
                   "PNG"});
    cli.addOption({"window", "Window size for --screenshot", "WxH", "1280x880"});
    cli.process(app);
    Options o;
    o.work = QDir(cli.value("work")).absolutePath();
    const QStringList size = cli.value("size").split('x');
    o.width = size.value(0).toInt();
    o.height = size.size() > 1 ? size.value(1).toInt() : o.width;
    if (o.width <= 0 || o.height <= 0) return fail("--size wants PX or WxH"), 2;
    o.steps = cli.value("steps").toInt();
    o.interval = cli.value("interval").toInt();
    o.drags = std::max(2, cli.value("drags").toInt());

    if (!captureDemo(o)) return 1;
    // demo.yaml reads ../../out/demo/*.cdb: the copy sits two folders down.
    const QString pipeline = sizeFolder(o) + "/pipelines/demo/demo.yaml";
    QDir().mkpath(sizeFolder(o) + "/pipelines/demo");
    QFile::remove(pipeline);
    if (!QFile::copy(DARKROOM_SOURCE_DIR "/docs/examples/demo.yaml", pipeline)) return fail("cannot copy demo.yaml"), 1;

    darkroom::Registry registry;
    const auto problems = registry.loadPlugins({DARKROOM_BENCH_PLUGIN_DIR});
    for (const auto& d : problems) std::fprintf(stderr, "%s\n", d.str().c_str());

    // The data range of the surface's scalar, for a manual colour-map range.
    double lo = 0, hi = 1;
    {
        darkroom::Diagnostics d;
        const darkroom::Graph g = darkroom::loadPipeline(pipeline.toStdString(), registry, d);
        darkroom::EvaluatorOptions eo;
        eo.inputBase = QFileInfo(pipeline).absolutePath().toStdString();
        darkroom::Evaluator ev(eo);
        lo = ev.evaluate(g, "surfaceColour", "usedMinimum").asFloat();
        hi = ev.evaluate(g, "surfaceColour", "usedMaximum").asFloat();
    }

    editor::MainWindow w(registry, problems);
    w.show();
    if (!QTest::qWaitForWindowExposed(&w)) return fail("the window was not exposed"), 1;
    Bench bench(w, o);
    QElapsedTimer open;
    open.start();
    if (!w.openPipeline(pipeline)) return fail("cannot open " + pipeline), 1;
    // Manual range over the data, so that dragging `maximum` recolours.
    w.document()->edit("range", [&](darkroom::Graph& g) {
        g.setParameter("surfaceColour", "range", darkroom::Value(std::string("manual")));
        g.setParameter("surfaceColour", "minimum", darkroom::Value(lo));
        g.setParameter("surfaceColour", "maximum", darkroom::Value(hi));
    });
    if (!bench.waitSettled(w.evaluation()->generation())) return 1;
    const double openMs = open.elapsed();
    w.scene()->clearSelection();

    if (cli.isSet("screenshot")) {
        // The README's picture: the graph at 1:1 from the colour mappings to
        // the occlusion, so that titles and values stay legible when the
        // page scales the picture down.
        const QStringList size = cli.value("window").split('x');
        w.resize(size.value(0).toInt(), size.value(1).toInt());
        QTest::qWait(100);
        w.resizeDocks({w.dock("graph")}, {w.height() * 3 / 8}, Qt::Vertical);
        QTest::qWait(200);
        w.graphView()->setTransform(QTransform());
        const QRectF from = w.scene()->nodeItem("surfaceColour")->sceneBoundingRect();
        w.graphView()->centerOn(from.left() + w.graphView()->viewport()->width() / 2.0 - 40,
                                from.top() + w.graphView()->viewport()->height() / 2.0 - 40);
        // One edit so that the badges show a frame in which some nodes ran.
        w.document()->edit("radius", [](darkroom::Graph& g) { g.setParameter("ao", "radius", darkroom::Value(0.1)); });
        if (!bench.waitSettled(w.evaluation()->generation())) return 1;
        QTest::qWait(300);
        w.statusBar()->clearMessage();
        w.renderView()->renderNow();
        // What the X server shows: the render view is a native OpenGL
        // window, which QWidget::grab() does not see.
        QCoreApplication::processEvents();
        if (!w.screen()->grabWindow(w.winId()).save(cli.value("screenshot")))
            return fail("cannot write " + cli.value("screenshot")), 1;
        std::printf("wrote %s\n", qPrintable(cli.value("screenshot")));
        w.document()->undoStack()->setClean();
        return 0;
    }

    struct Target {
        QString label, node, port;
        int direction;
        double fullValue;
    };
    const std::vector<Target> targets = {
        {"ColorMapping maximum (surfaceColour)", "surfaceColour", "maximum", -1, lo + 0.7 * (hi - lo)},
        {"SSAO radius (ao)", "ao", "radius", +1, 0.1},
    };

    if (qEnvironmentVariableIsSet("BENCH_EDITOR_DETAIL")) {
        auto frameTime = [&](const std::function<void()>& change) {
            std::vector<double> t;
            for (int i = 0; i < 8; ++i) {
                bool swapped = false;
                auto c = QObject::connect(w.renderView(), &editor::RenderView::frameSwapped, [&] { swapped = true; });
                QElapsedTimer e;
                e.start();
                change();
                w.renderView()->requestFrame();
                while (!swapped) QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents, 5);
                t.push_back(e.nsecsElapsed() / 1e6);
                QObject::disconnect(c);
                QTest::qWait(20);
            }
            return percentile(t, 0.5);
        };
        int k = 0;
        std::fprintf(stderr, "frame: render view only %.1f ms\n", frameTime([] {}));
        std::fprintf(stderr, "frame: + a badge %.1f ms\n", frameTime([&] {
            w.scene()->nodeItem("ao")->setTiming(0.001 * ++k, true, true);
        }));
        std::fprintf(stderr, "frame: + the status line %.1f ms\n", frameTime([&] {
            w.statusBar()->showMessage(QString::number(++k));
        }));
        std::fprintf(stderr, "frame: + a number field %.1f ms\n", frameTime([&] {
            w.scene()->nodeItem("ao")->paramWidget("radius")->setValue(darkroom::Value(0.08 + 0.001 * (++k % 5)));
        }));
        // What a new full-resolution image costs the view: the same buffer
        // set again is uploaded and mapped again.
        const darkroom::BufferPtr shown = w.renderView()->image();
        std::fprintf(stderr, "frame: + a new %d x %d image (upload, mapping) %.1f ms\n", shown->width(),
                     shown->height(), frameTime([&] { w.renderView()->setImage(shown); }));
        for (int i = 0; i < 3; ++i) {
            QElapsedTimer t;
            t.start();
            w.graphView()->viewport()->repaint();
            const double graph = t.nsecsElapsed() / 1e6;
            t.restart();
            w.renderView()->renderNow();
            const double render = t.nsecsElapsed() / 1e6;
            t.restart();
            w.repaint();
            const double window = t.nsecsElapsed() / 1e6;
            std::fprintf(stderr, "repaint: graph view %.1f ms, render view %.1f ms, window %.1f ms\n", graph, render, window);
        }
    }
    std::printf("# darkroom-editor input-to-pixels, demo pipeline at %d x %d\n\n", o.width, o.height);
    std::printf("opened and evaluated at full resolution in %.0f ms (cold: reading the three databases)\n", openMs);
    std::printf("drag: %d moves of %d px every %d ms; %d drags per value, the first right after opening\n\n",
                o.steps, o.pixelsPerStep, o.interval, o.drags);
    std::printf("| value | drag | events | frames | preview size | preview compute median ms | input-to-pixels median ms | p90 ms | max ms | settle ms (compute ms) |\n");
    std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
    QStringList results;
    for (const auto& t : targets) {
        std::vector<double> warm;
        std::vector<double> warmSettle;
        for (int i = 0; i < o.drags; ++i) {
            DragResult r;
            if (!bench.drag(t.node, t.port, i % 2 ? -t.direction : t.direction, &r)) return 1;
            std::printf("| %s | %s | %zu | %d | %s | %.1f | %.1f | %.1f | %.1f | %.0f (%.0f) |\n", qPrintable(t.label),
                        i == 0 ? "1 (first)" : qPrintable(QString::number(i + 1)), r.latencies.size(), r.frames,
                        qPrintable(levelsText(r.levels)), percentile(r.previewCompute, 0.5),
                        percentile(r.latencies, 0.5), percentile(r.latencies, 0.9), percentile(r.latencies, 1.0),
                        r.settleMs, r.settleCompute);
            std::fflush(stdout);
            if (qEnvironmentVariableIsSet("BENCH_EDITOR_DETAIL")) {
                std::fprintf(stderr, "UI handling per move: median %.1f ms, max %.1f ms; result to screen median %.1f ms max %.1f\n",
                             percentile(r.handling, 0.5), percentile(r.handling, 1.0), percentile(r.paint, 0.5),
                             percentile(r.paint, 1.0));
                for (const auto& n : bench.lastPreview_.nodes)
                    std::fprintf(stderr, "  %-28s %s %.2f ms\n", n.node.c_str(), n.ran ? "ran   " : "cached", n.seconds * 1e3);
                std::fprintf(stderr, "  preview wall %.2f ms\n", bench.lastPreview_.seconds * 1e3);
            }
            if (i > 0) {
                warm.insert(warm.end(), r.latencies.begin(), r.latencies.end());
                warmSettle.push_back(r.settleMs);
            }
        }
        double full = -1, fullCompute = -1;
        if (!bench.fullFrame(t.node, t.port, t.fullValue, &full, &fullCompute)) return 1;
        std::printf("| %s | without preview | 1 | 1 | full | – | %.1f | – | – | (%.0f) |\n", qPrintable(t.label), full,
                    fullCompute);
        if (qEnvironmentVariableIsSet("BENCH_EDITOR_DETAIL"))
            for (const auto& n : bench.lastFull_.nodes)
                if (n.ran) std::fprintf(stderr, "  full frame: %-28s %.2f ms\n", n.node.c_str(), n.seconds * 1e3);
        std::printf("| %s | **warm drags** | %zu | | | | **%.1f** | %.1f | %.1f | **%.0f** |\n", qPrintable(t.label),
                    warm.size(), percentile(warm, 0.5), percentile(warm, 0.9), percentile(warm, 1.0),
                    percentile(warmSettle, 0.5));
        results << QString::asprintf(
            "RESULT value=%s median_ms=%.1f p90_ms=%.1f settle_ms=%.0f full_frame_ms=%.1f ratio_full_over_median=%.1f",
            qPrintable(t.node + "." + t.port), percentile(warm, 0.5), percentile(warm, 0.9), percentile(warmSettle, 0.5),
            full, full / std::max(percentile(warm, 0.5), 1e-3));
        std::fflush(stdout);
    }
    std::printf("\n%s\n", qPrintable(results.join('\n')));
    w.document()->undoStack()->setClean();
    return 0;
}
