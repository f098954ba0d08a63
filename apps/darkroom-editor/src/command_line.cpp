#include "command_line.h"

#include <set>
#include <string_view>

namespace editor {
namespace {

// Options QGuiApplication and QApplication read (with one dash or two);
// those in the first set take a value.
const std::set<std::string_view> kQtWithValue = {
    "platform", "platformpluginpath", "platformtheme", "plugin", "qwindowgeometry", "geometry",
    "qwindowtitle", "title", "qwindowicon", "style", "stylesheet", "session", "display", "name",
    "visual", "qmljsdebugger"};
const std::set<std::string_view> kQtFlags = {"reverse", "nograb", "dograb", "sync", "widgetcount"};

}  // namespace

CommandLine parseCommandLine(int argc, char** argv) {
    CommandLine cl;
    for (int i = 1; i < argc; ++i) {
        const std::string_view a = argv[i];
        if (a == "-h" || a == "--help") {
            cl.help = true;
            return cl;
        }
        if (a.size() < 2 || a[0] != '-') continue;  // a file
        std::string_view name = a.substr(a[1] == '-' ? 2 : 1);
        if (const auto eq = name.find('='); eq != std::string_view::npos) name = name.substr(0, eq);
        if (kQtFlags.count(name)) continue;
        if (kQtWithValue.count(name)) {
            if (a.find('=') == std::string_view::npos) ++i;  // its value
            continue;
        }
        if (cl.error.empty()) cl.error = "unknown option '" + std::string(a) + "'";
    }
    return cl;
}

std::string usageText() {
    return "Usage: darkroom-editor [PIPELINE.yaml] [DATABASE.cdb ...]\n"
           "\n"
           "The Darkroom editor: a node graph of shading passes with a live render view,\n"
           "and an explorer of Cinema databases (parallel coordinates, an image grid and\n"
           "linked selection). It reads and writes the same pipelines as `darkroom run`.\n"
           "\n"
           "Arguments:\n"
           "  PIPELINE.yaml    open a pipeline\n"
           "  DATABASE.cdb     open a Cinema database (its .cdb folder or its data.csv) in\n"
           "                   the browser and the explorer\n"
           "\n"
           "Options:\n"
           "  -h, --help       print this help and exit\n"
           "  Qt's own options (-platform NAME, -style NAME, ...) are passed on to Qt.\n"
           "\n"
           "Environment:\n"
           "  DARKROOM_PLUGIN_PATH  more folders to load plugins from (':'-separated)\n"
           "  QT_QPA_PLATFORM       Qt's window system (xcb, wayland, offscreen)\n"
           "\n"
           "In the editor, Help > Documentation shows the manual (docs/editor.md) and\n"
           "Help > Keyboard shortcuts the keys.\n";
}

}  // namespace editor
