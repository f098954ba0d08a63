// MainWindow: menus, files (pipelines, Cinema databases, export), recent
// files, drag and drop.
#include "main_window.h"

#include "autosave.h"

#include "cinema_panel.h"
#include "display.h"
#include "explorer_panel.h"
#include "document.h"
#include "graph_scene.h"
#include "graph_view.h"
#include "palette.h"
#include "render_view.h"

#include <darkroom/data/image_io.h>
#include <darkroom/srgb.h>

#include <QAction>
#include <QCloseEvent>
#include <QDockWidget>
#include <QDragEnterEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QPlainTextEdit>
#include <QSettings>
#include <QStatusBar>

namespace editor {
namespace {

constexpr int kMaxRecent = 8;
const char* kPipelineFilter = "Pipelines (*.yaml *.yml);;All files (*)";

bool isCinemaPath(const QString& p) {
    return p.endsWith(".cdb") || p.endsWith(".cdb/") || p.endsWith("data.csv");
}

}  // namespace

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, [this] {
        if (maybeSave()) doc_->clear();
    });
    file->addAction(tr("&Open…"), QKeySequence::Open, this, [this] {
        if (!maybeSave()) return;
        const QString f = QFileDialog::getOpenFileName(this, tr("Open pipeline"), doc_->folder(), tr(kPipelineFilter));
        if (!f.isEmpty()) openPipeline(f);
    });
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    recoverMenu_ = file->addMenu(tr("Recover &autosave"));
    recoverMenu_->setObjectName("recoverMenu");
    connect(recoverMenu_, &QMenu::aboutToShow, this, &MainWindow::updateRecoverMenu);
    file->addAction(tr("Open &Cinema database…"), this, [this] {
        const QString f = QFileDialog::getExistingDirectory(this, tr("Open Cinema database (.cdb folder)"), doc_->folder());
        if (!f.isEmpty()) openCinema(f);
    });
    file->addSeparator();
    auto saveAs = [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Save pipeline"), doc_->folder(), tr(kPipelineFilter));
        return !f.isEmpty() && savePipeline(f);
    };
    file->addAction(tr("&Save"), QKeySequence::Save, this, [this, saveAs] {
        if (doc_->path().isEmpty()) saveAs();
        else savePipeline(doc_->path());
    });
    file->addAction(tr("Save &As…"), QKeySequence::SaveAs, this, saveAs);
    file->addAction(tr("&Export view…"), this, [this] {
        const QString f = QFileDialog::getSaveFileName(this, tr("Export view"), doc_->folder(),
                                                       tr("PNG (*.png);;OpenEXR, every channel (*.exr)"));
        if (!f.isEmpty()) exportView(f);
    });
    file->addSeparator();
    file->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    QAction* undo = doc_->undoStack()->createUndoAction(this);
    undo->setShortcut(QKeySequence::Undo);
    QAction* redo = doc_->undoStack()->createRedoAction(this);
    redo->setShortcut(QKeySequence::Redo);
    edit->addAction(undo);
    edit->addAction(redo);
    edit->addSeparator();
    edit->addAction(tr("&Add node…"), QKeySequence(Qt::CTRL | Qt::Key_Space), palette_, &Palette::focusSearch);
    QAction* del = edit->addAction(tr("&Delete selection"), scene_, &GraphScene::deleteSelection);
    del->setShortcut(QKeySequence::Delete);
    del->setShortcutContext(Qt::WidgetShortcut);  // the graph view's Delete key, not line edits'
    graphView_->addAction(del);

    QMenu* view = menuBar()->addMenu(tr("&View"));
    view->addAction(tr("Fit &graph"), this, [this] { graphView_->fitAll(); });
    view->addAction(tr("Fit &image"), QKeySequence(Qt::Key_F), render_, &RenderView::fit);
    view->addSeparator();
    for (const char* name : {"graph", "palette", "cinema", "explorer", "log"})
        if (QDockWidget* d = dock(name)) view->addAction(d->toggleViewAction());
    updateRecentMenu();
    updateRecoverMenu();
    buildHelpMenu();
}

bool MainWindow::openPipeline(const QString& path) {
    QStringList messages;
    shownNode_.clear();  // a new pipeline starts with its own default view
    const bool ok = doc_->load(path, messages);
    for (const auto& m : messages) logMessage(m);
    if (!ok) {
        statusBar()->showMessage(messages.isEmpty() ? tr("Cannot open %1").arg(path) : messages.front(), 10000);
        return false;
    }
    addRecent(doc_->path());
    graphView_->fitAll();
    restoreExplorer();
    statusBar()->showMessage(messages.isEmpty() ? tr("Opened %1").arg(path)
                                                : tr("Opened %1 with %2 problems (see the log)").arg(path).arg(messages.size()),
                             8000);
    return true;
}

bool MainWindow::savePipeline(const QString& path) {
    QString err;
    if (!doc_->save(path, &err)) {
        logMessage(err);
        QMessageBox::warning(this, tr("Save failed"), err);
        return false;
    }
    addRecent(doc_->path());
    statusBar()->showMessage(tr("Saved %1").arg(path), 5000);
    return true;
}

bool MainWindow::openCinema(const QString& path, std::int64_t selectRow, const QString& selectParameters) {
    QString err;
    // Absolute: the reader it drives resolves relative paths against the
    // pipeline's folder, not the editor's working folder.
    if (!cinema_->open(QFileInfo(path).absoluteFilePath(), &err, selectRow, selectParameters)) {
        logMessage(err);
        statusBar()->showMessage(err, 10000);
        return false;
    }
    explorer_->setDatabase(*cinema_->database(), cinema_->entries());
    explorer_->setCurrent(cinema_->currentEntry());
    updateExplorerPipeline();
    for (const char* name : {"cinema", "explorer"})
        if (QDockWidget* d = dock(name)) {
            d->show();
            d->raise();
        }
    return true;
}

bool MainWindow::exportView(const QString& path) {
    const auto& image = render_->image();
    if (!image) {
        statusBar()->showMessage(tr("Nothing to export: select a node with an image output"), 8000);
        return false;
    }
    try {
        if (path.endsWith(".exr", Qt::CaseInsensitive)) {
            darkroom::writeImage(*image, path.toStdString());
        } else {
            // What the view shows (false colour, normals, ...), not the raw
            // channels: decode the display's sRGB back to the linear floats
            // writeImage expects.
            const QImage d = renderDisplay(*image, render_->mode());
            auto b = darkroom::makeCpuBuffer(d.width(), d.height(), {{"R"}, {"G"}, {"B"}, {"A"}});
            float* ch[4] = {b->writeFloat("R"), b->writeFloat("G"), b->writeFloat("B"), b->writeFloat("A")};
            for (int y = 0; y < d.height(); ++y) {
                const QRgb* row = reinterpret_cast<const QRgb*>(d.constScanLine(y));
                for (int x = 0; x < d.width(); ++x) {
                    const std::size_t i = std::size_t(y) * d.width() + x;
                    ch[0][i] = darkroom::srgbToLinear(qRed(row[x]) / 255.0f);
                    ch[1][i] = darkroom::srgbToLinear(qGreen(row[x]) / 255.0f);
                    ch[2][i] = darkroom::srgbToLinear(qBlue(row[x]) / 255.0f);
                    ch[3][i] = qAlpha(row[x]) / 255.0f;
                }
            }
            darkroom::writeImage(*b, path.toStdString());
        }
    } catch (const std::exception& e) {
        logMessage(QString::fromStdString(e.what()));
        statusBar()->showMessage(QString::fromStdString(e.what()), 10000);
        return false;
    }
    statusBar()->showMessage(tr("Exported %1").arg(path), 5000);
    return true;
}

void MainWindow::addRecent(const QString& path) {
    QSettings s;
    QStringList r = s.value("recentFiles").toStringList();
    r.removeAll(path);
    r.prepend(path);
    while (r.size() > kMaxRecent) r.removeLast();
    s.setValue("recentFiles", r);
    updateRecentMenu();
}

void MainWindow::updateRecentMenu() {
    if (!recentMenu_) return;
    recentMenu_->clear();
    for (const QString& f : QSettings().value("recentFiles").toStringList())
        recentMenu_->addAction(f, this, [this, f] {
            if (maybeSave()) openPipeline(f);
        });
    recentMenu_->setEnabled(!recentMenu_->isEmpty());
}

void MainWindow::offerRecovery(const std::function<bool(const Recovery&)>& ask) {
    const std::vector<Recovery> left = Autosave::leftBehind();
    if (left.empty()) return;
    // The newest is the session that crashed last. Older ones were offered
    // at earlier starts (or ended with it): set aside, not asked about again.
    for (std::size_t i = 1; i < left.size(); ++i) Autosave::putAside(left[i]);
    const Recovery& r = left.front();
    const QString what = r.originalPath.isEmpty() ? tr("an unsaved pipeline") : r.originalPath;
    bool yes;
    if (ask) {
        yes = ask(r);
    } else {
        QString text = tr("The last darkroom-editor ended without saving %1 (autosaved %2).\nRestore it?")
                           .arg(what, r.savedAt);
        if (left.size() > 1)
            text += tr("\n\n%1 older autosaves were set aside: File > Recover autosave.").arg(left.size() - 1);
        yes = QMessageBox::question(this, tr("Recover unsaved work"), text, QMessageBox::Yes | QMessageBox::No,
                                    QMessageBox::Yes) == QMessageBox::Yes;
    }
    if (!yes) Autosave::drop(r);
    else if (!recover(r)) Autosave::putAside(r);  // unreadable now: kept, never lost
    updateRecoverMenu();
}

bool MainWindow::recover(const Recovery& r) {
    QStringList messages;
    const bool ok = Autosave::restore(r, doc_, messages);
    if (ok) logMessage(tr("Restored %1 from %2").arg(r.originalPath.isEmpty() ? tr("an unsaved pipeline") : r.originalPath, r.file));
    for (const QString& m : messages) logMessage(m);
    return ok;
}

void MainWindow::updateRecoverMenu() {
    if (!recoverMenu_) return;
    recoverMenu_->clear();
    for (const Recovery& r : Autosave::setAside())
        recoverMenu_->addAction(tr("%1 (autosaved %2)").arg(r.originalPath.isEmpty() ? tr("unsaved pipeline") : r.originalPath, r.savedAt),
                                this, [this, r] {
                                    if (maybeSave() && recover(r)) statusBar()->showMessage(tr("Recovered %1").arg(r.file), 8000);
                                });
    recoverMenu_->setEnabled(!recoverMenu_->isEmpty());
}

void MainWindow::updateTitle() {
    const QString name = doc_->path().isEmpty() ? tr("untitled") : QFileInfo(doc_->path()).fileName();
    setWindowTitle(name + (doc_->undoStack()->isClean() ? QString() : QStringLiteral(" *")) +
                   QStringLiteral(" — Darkroom"));
}

bool MainWindow::maybeSave() {
    if (doc_->undoStack()->isClean() || !isVisible()) return true;
    const auto b = QMessageBox::question(this, tr("Unsaved changes"), tr("Save the changes first?"),
                                         QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (b == QMessageBox::Cancel) return false;
    if (b == QMessageBox::Save) return !doc_->path().isEmpty() && savePipeline(doc_->path());
    return true;
}

void MainWindow::dragEnterEvent(QDragEnterEvent* e) {
    for (const QUrl& u : e->mimeData()->urls()) {
        const QString p = u.toLocalFile();
        if (p.endsWith(".yaml") || p.endsWith(".yml") || isCinemaPath(p)) {
            e->acceptProposedAction();
            return;
        }
    }
}

void MainWindow::dropEvent(QDropEvent* e) {
    for (const QUrl& u : e->mimeData()->urls()) {
        const QString p = u.toLocalFile();
        if (isCinemaPath(p)) openCinema(p);
        else if ((p.endsWith(".yaml") || p.endsWith(".yml")) && maybeSave()) openPipeline(p);
    }
    e->acceptProposedAction();
}

void MainWindow::closeEvent(QCloseEvent* e) {
    if (maybeSave()) {
        saveLayout();
        autosave_->discard();  // a clean exit leaves nothing to recover
        e->accept();
    } else {
        e->ignore();
    }
}

void MainWindow::saveLayout() const {
    QSettings s;
    s.setValue("layout/version", kLayoutVersion);
    s.setValue("layout/geometry", saveGeometry());
    s.setValue("layout/state", saveState(kLayoutVersion));
}

bool MainWindow::restoreLayout() {
    QSettings s;
    if (s.value("layout/version").toInt() != kLayoutVersion) return false;
    const bool ok = restoreGeometry(s.value("layout/geometry").toByteArray()) &&
                    restoreState(s.value("layout/state").toByteArray(), kLayoutVersion);
    // The Cinema browser belongs to an open database, not to the last session.
    for (const char* name : {"cinema", "explorer"})
        if (QDockWidget* d = dock(name); d && !cinema_->database() && d->isVisible()) {
            d->hide();
            if (QString(name) == "explorer") dock("graph")->raise();  // its tab was the current one
        }
    return ok;
}

}  // namespace editor
