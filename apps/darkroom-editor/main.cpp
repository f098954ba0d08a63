// darkroom-editor: the node-graph editor. Plugins come from the same search
// path as the runner's (next to the executable, DARKROOM_PLUGIN_PATH).
#include "command_line.h"
#include "main_window.h"

#include <darkroom/core/registry.h>

#include <QApplication>
#include <QTimer>

#include <cstdio>

int main(int argc, char** argv) {
    // Before QApplication, which needs a display: --help and bad options
    // answer on a headless machine too.
    const editor::CommandLine cl = editor::parseCommandLine(argc, argv);
    if (cl.help) {
        std::fputs(editor::usageText().c_str(), stdout);
        return 0;
    }
    if (!cl.error.empty()) {
        std::fprintf(stderr, "darkroom-editor: %s (see darkroom-editor --help)\n", cl.error.c_str());
        return 2;
    }
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
            if (a.endsWith(".cdb") || a.endsWith(".cdb/") || a.endsWith("data.csv")) w.openCinema(a);
            else w.openPipeline(a);
        }
        // An editor that crashed (a plugin failing inside execute() takes the
        // process with it) left its unsaved graph behind: offer it back.
        w.offerRecovery();
    });
    return app.exec();
}
