#pragma once
// Helpers shared by the GUI test executables: the build's plugins, settings
// kept out of the user's, waiting for the live evaluation, screenshots.
#include <darkroom/core/registry.h>

#include <QPoint>
#include <QString>

class QWidget;

namespace editor {
class MainWindow;
}

namespace guitest {

// Every plugin the build produced (loaded once).
darkroom::Registry& registry();
// Call from initTestCase: QSettings and recent files go to a fresh folder,
// the screenshot folder exists.
void prepare();
// Under the sanitizers only (DARKROOM_SANITIZED): keeps Mesa's OpenGL driver
// loaded to the end of the process (gui_support.cpp says why). prepare()
// calls it; a test without prepare() calls it from initTestCase.
void keepGlDriverLoaded();
// Forgets saved settings (layout, recent files): a window starts with defaults.
void clearSettings();
// Waits until no evaluation waits, runs or is about to settle, then lets
// the result reach the screen. False after `ms`.
bool waitIdle(editor::MainWindow& w, int ms = 60000);
// Saves a screenshot of `widget` to <build>/tests/gui-artifacts/<name>.png.
bool screenshot(QWidget* widget, const QString& name);
// A port's position in the graph view's viewport.
QPoint portPos(editor::MainWindow& w, const QString& node, const QString& port, bool output);

}  // namespace guitest
