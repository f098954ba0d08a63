// darkroom-editor: the node-graph editor. Plugins come from the same search
// path as the runner's (next to the executable, DARKROOM_PLUGIN_PATH).
#include "main_window.h"

#include <darkroom/framework/registry.h>

#include <QApplication>
#include <QTimer>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("darkroom");
    QApplication::setApplicationName("darkroom-editor");
    darkroom::Registry registry;
    const auto problems = registry.loadPlugins(darkroom::Registry::defaultSearchPath());
    editor::MainWindow w(registry, problems);
    w.show();
    // Opened once the window has its final size, so the graph is fitted to it.
    QTimer::singleShot(0, &w, [&w] {
        for (const QString& a : QApplication::arguments().mid(1)) {
            if (a.endsWith(".cdb") || a.endsWith(".cdb/")) w.openCinema(a);
            else w.openPipeline(a);
        }
    });
    return app.exec();
}
