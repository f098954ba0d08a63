#include "gui_support.h"

#include "evaluation.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "main_window.h"
#include "render_view.h"

#include <QDir>
#include <QScreen>
#include <QWindow>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

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
}

void clearSettings() {
    QSettings s;
    s.clear();
    s.sync();
}

bool waitIdle(editor::MainWindow& w, int ms) {
    if (!QTest::qWaitFor([&] { return !w.evaluation()->busy(); }, ms)) return false;
    QCoreApplication::processEvents();
    w.renderView()->repaint();
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
