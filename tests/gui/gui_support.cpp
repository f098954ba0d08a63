#include "gui_support.h"

#include "evaluation.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "main_window.h"
#include "render_view.h"

#include <QDir>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QScreen>
#include <QWindow>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <dlfcn.h>
#include <link.h>

#include <cstdlib>
#include <cstring>

namespace guitest {

darkroom::Registry& registry() {
    static darkroom::Registry r;
    static const bool loaded = [] {
        for (const auto& p : r.loadPlugins({DARKROOM_PLUGIN_DIR})) qWarning("%s", p.str().c_str());
        return true;
    }();
    (void)loaded;
    return r;
}

void prepare() {
    QStandardPaths::setTestModeEnabled(true);
    static QTemporaryDir settings;
    QSettings::setPath(QSettings::NativeFormat, QSettings::UserScope, settings.path());
    QCoreApplication::setOrganizationName("darkroom-test");
    QCoreApplication::setApplicationName("darkroom-editor");
    QDir().mkpath(DARKROOM_GUI_ARTIFACTS);
    clearSettings();
    keepGlDriverLoaded();
}

// Mesa unloads its DRI driver (llvmpipe: swrast_dri.so) when the X display
// closes, before LeakSanitizer scans at exit. The driver's caches, reachable
// from its globals while it is loaded, would then be reported as leaks from
// an unloaded module that no suppression can name (tests/sanitizers/lsan.supp).
// A context made here loads the driver, and RTLD_NODELETE keeps it, with
// what it loaded, until the process ends. Nothing changes outside the
// sanitizer run.
void keepGlDriverLoaded() {
    if (!std::getenv("DARKROOM_SANITIZED")) return;
    QOffscreenSurface surface;
    surface.create();
    QOpenGLContext context;
    if (!context.create() || !context.makeCurrent(&surface)) return;
    dl_iterate_phdr(
        [](dl_phdr_info* info, std::size_t, void*) {
            const char* name = info->dlpi_name;
            const std::size_t n = name ? std::strlen(name) : 0;
            if (n > 7 && std::strcmp(name + n - 7, "_dri.so") == 0)
                (void)dlopen(name, RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);  // never closed, on purpose
            return 0;
        },
        nullptr);
    context.doneCurrent();
}

void clearSettings() {
    QSettings s;
    s.clear();
    s.sync();
}

bool waitIdle(editor::MainWindow& w, int ms) {
    if (!QTest::qWaitFor([&] { return !w.evaluation()->busy(); }, ms)) return false;
    QCoreApplication::processEvents();
    w.renderView()->renderNow();
    return true;
}

bool screenshot(QWidget* widget, const QString& name) {
    const QString path = QStringLiteral(DARKROOM_GUI_ARTIFACTS "/") + name + ".png";
    // What the X server shows: QWidget::grab() leaves out what QPainter
    // draws over an OpenGL widget (the render view's messages).
    QWidget* top = widget->window();
    if (widget->isVisible() && top->windowHandle() && top->windowHandle()->isExposed()) {
        QCoreApplication::processEvents();
        const QPoint at = widget->mapTo(top, QPoint(0, 0));
        const QPixmap shot = top->screen()->grabWindow(top->winId(), at.x(), at.y(), widget->width(), widget->height());
        if (!shot.isNull()) return shot.save(path);
    }
    return widget->grab().save(path);
}

QPoint portPos(editor::MainWindow& w, const QString& node, const QString& port, bool output) {
    return w.graphView()->mapFromScene(w.scene()->portPos(node, port, output));
}

}  // namespace guitest
