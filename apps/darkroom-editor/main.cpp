// darkroom-editor: the node-graph editor. Plugins come from the same search
// path as the runner's (next to the executable, DARKROOM_PLUGIN_PATH).
#include "autosave.h"
#include "document.h"
#include "main_window.h"

#include <darkroom/core/registry.h>

#include <QApplication>
#include <QMessageBox>
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
        // An editor that crashed (a plugin failing inside execute() takes the
        // process with it) left its unsaved graph behind: offer it back.
        for (const editor::Recovery& r : editor::Autosave::leftBehind()) {
            const QString what = r.originalPath.isEmpty() ? QString("an unsaved pipeline") : r.originalPath;
            const auto answer = QMessageBox::question(
                &w, "Recover unsaved work",
                "An earlier darkroom-editor ended without saving " + what + " (autosaved " + r.savedAt +
                    ").\nRestore it?",
                QMessageBox::Yes | QMessageBox::No, QMessageBox::Yes);
            if (answer == QMessageBox::Yes) {
                QStringList messages;
                if (editor::Autosave::restore(r, w.document(), messages))
                    w.logMessage("Restored " + what + " from " + r.file);
                for (const QString& m : messages) w.logMessage(m);
                break;
            }
            editor::Autosave::drop(r);
        }
    });
    return app.exec();
}
