// darkroom-editor: the node-graph editor. Plugins come from the same search
// path as the runner's (next to the executable, DARKROOM_PLUGIN_PATH).
#include "main_window.h"

#include <darkroom/framework/registry.h>

#include <QApplication>

int main(int argc, char** argv) {
    QApplication app(argc, argv);
    QApplication::setOrganizationName("darkroom");
    QApplication::setApplicationName("darkroom-editor");
    darkroom::Registry registry;
    const auto problems = registry.loadPlugins(darkroom::Registry::defaultSearchPath());
    editor::MainWindow w(registry, problems);
    w.show();
    const QStringList args = QApplication::arguments().mid(1);
    for (const QString& a : args) {
        if (a.endsWith(".cdb") || a.endsWith(".cdb/")) w.openCinema(a);
        else w.openPipeline(a);
    }
    return app.exec();
}
