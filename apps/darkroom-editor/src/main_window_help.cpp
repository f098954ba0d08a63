// MainWindow: the Help menu. The manual is docs/editor.md, built into the
// editor as a Qt resource (with its pictures), so it is there offline and
// always matches the build; the shortcuts list is made from the menus' own
// shortcuts plus the keys of the views, which have no menu entry.
#include "main_window.h"

#include <QDialog>
#include <QFile>
#include <QImage>
#include <QKeySequence>
#include <QMenuBar>
#include <QTextBrowser>
#include <QVBoxLayout>

#include <algorithm>

namespace editor {
namespace {

// Keys that act in a view rather than through a menu.
const char* const kViewKeys[][2] = {
    {"Tab", "Graph: quick-add menu at the cursor (type, Up/Down, Enter)"},
    {"Wheel", "Graph and render view: zoom about the cursor"},
    {"Middle drag, Alt+drag", "Graph: pan"},
    {"Drag on a number field", "Change the value (Ctrl: finer); a click edits the text"},
    {"F, double-click", "Render view: fit the image"},
    {"1", "Render view: 1:1"},
    {"Drag", "Render view: pan"},
    {"Drag on an axis", "Explorer: brush a range (replaces that axis' brushes)"},
    {"Shift+drag on an axis", "Explorer: add a brush on that axis"},
    {"Drag inside a brush", "Explorer: move the brush"},
    {"Click on an axis", "Explorer: clear that axis' brushes"},
    {"Click a polyline or a picture", "Explorer: shade that row in the render view"},
    {"Arrow keys, Page Up/Down", "Explorer grid: move the current row"},
};

// Pictures of the manual are screenshots of the whole window: shown at the
// browser's width, not at 1:1.
class DocBrowser : public QTextBrowser {
public:
    QVariant loadResource(int type, const QUrl& name) override {
        const QVariant v = QTextBrowser::loadResource(type, name);
        if (type != QTextDocument::ImageResource) return v;
        QImage image;
        if (v.canConvert<QByteArray>()) image.loadFromData(v.toByteArray());
        if (image.isNull()) image = qvariant_cast<QImage>(v);
        const int wide = std::max(200, viewport()->width() - 24);
        if (image.isNull() || image.width() <= wide) return v;
        return image.scaledToWidth(wide, Qt::SmoothTransformation);
    }
};

QDialog* helpWindow(QWidget* parent, const QString& title, const QString& objectName) {
    if (auto* b = parent->findChild<QTextBrowser*>(objectName)) return qobject_cast<QDialog*>(b->window());
    auto* d = new QDialog(parent);
    d->setWindowTitle(title);
    d->resize(760, 640);
    auto* lay = new QVBoxLayout(d);
    auto* b = new DocBrowser;
    b->setObjectName(objectName);
    b->setOpenExternalLinks(true);
    lay->addWidget(b);
    return d;
}

void collectShortcuts(const QList<QAction*>& actions, QString& rows) {
    for (QAction* a : actions) {
        if (a->menu()) collectShortcuts(a->menu()->actions(), rows);
        if (a->shortcut().isEmpty()) continue;
        rows += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>")
                    .arg(a->shortcut().toString(QKeySequence::NativeText).toHtmlEscaped(),
                         a->text().remove('&').toHtmlEscaped());
    }
}

}  // namespace

void MainWindow::buildHelpMenu() {
    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&Documentation"), QKeySequence::HelpContents, this, [this] {
        QDialog* d = helpWindow(this, tr("darkroom-editor documentation"), QStringLiteral("helpDocs"));
        auto* b = d->findChild<QTextBrowser*>();
        if (QFile::exists(QStringLiteral(":/docs/editor.md")))
            b->setSource(QUrl(QStringLiteral("qrc:/docs/editor.md")), QTextDocument::MarkdownResource);
        else
            b->setPlainText(tr("This build has no documentation built in: see docs/editor.md in the sources."));
        d->show();
        d->raise();
    });
    help->addAction(tr("&Keyboard shortcuts"), this, [this] {
        QDialog* d = helpWindow(this, tr("Keyboard shortcuts"), QStringLiteral("helpShortcuts"));
        QString rows;
        collectShortcuts(menuBar()->actions(), rows);
        for (const auto& k : kViewKeys)
            rows += QStringLiteral("<tr><td><b>%1</b></td><td>%2</td></tr>").arg(tr(k[0]).toHtmlEscaped(), tr(k[1]).toHtmlEscaped());
        d->findChild<QTextBrowser*>()->setHtml(
            QStringLiteral("<table cellpadding=4>") + rows + QStringLiteral("</table>"));
        d->show();
        d->raise();
    });
}

}  // namespace editor
