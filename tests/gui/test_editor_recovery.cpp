// Crash recovery: a plugin crashing inside execute() takes the editor down
// (no signal can be caught safely in-process), so unsaved edits are autosaved
// a second after each change and offered back at the next start. Saving, or
// a clean exit, leaves nothing behind.
#include "autosave.h"
#include "document.h"
#include "gui_support.h"
#include "main_window.h"
#include "test_support.h"

#include <darkroom/core/pipeline.h>

#include <QFile>
#include <QProcess>
#include <QUndoStack>
#include <QtTest>

using editor::Autosave;
using editor::MainWindow;

namespace {

const char* kPipeline = R"(darkroom: 1
nodes:
  colour:
    type: ColorMapping
    parameters:
      channel: value
edges: []
)";

// The pid of a process that has ended: an autosave named after it belongs to
// an editor that is no longer running.
qint64 deadPid() {
    QProcess p;
    p.start("true", {});
    p.waitForFinished();
    return p.processId() > 0 ? p.processId() : 999999;
}

}  // namespace

class RecoveryTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { guitest::prepare(); }
    void unsavedEditsAreOfferedBackAfterACrash();
    void savingLeavesNothingBehind();
};

void RecoveryTest::unsavedEditsAreOfferedBackAfterACrash() {
    darkroom::test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("pipeline.yaml"));
    darkroom::test::writeText(path.toStdString(), kPipeline);
    std::string edited;
    QString crashed;
    {
        MainWindow w(guitest::registry(), {});
        QVERIFY(w.openPipeline(path));
        QVERIFY(w.document()->edit("colour map", [](darkroom::Graph& g) {
            g.setParameter("colour", "colormap", darkroom::Value("inferno"));
        }).isEmpty());
        edited = darkroom::serializePipeline(w.document()->graph());
        QTRY_VERIFY_WITH_TIMEOUT(!w.autosave()->file().isEmpty() && QFile::exists(w.autosave()->file()), 5000);
        // The editor "crashes": its autosave stays, under a pid no longer running.
        crashed = Autosave::folder() + "/" + QString::number(deadPid()) + ".yaml";
        QFile::remove(crashed);
        QVERIFY(QFile::rename(w.autosave()->file(), crashed));
    }
    const auto left = Autosave::leftBehind();
    QCOMPARE(int(left.size()), 1);
    QCOMPARE(left[0].file, crashed);
    QCOMPARE(left[0].originalPath, QFileInfo(path).absoluteFilePath());

    MainWindow next(guitest::registry(), {});
    QStringList messages;
    QVERIFY(Autosave::restore(left[0], next.document(), messages));
    QCOMPARE(darkroom::serializePipeline(next.document()->graph()), edited);
    QCOMPARE(next.document()->path(), QFileInfo(path).absoluteFilePath());  // relative paths resolve there
    QVERIFY(!next.document()->undoStack()->isClean());                      // still unsaved
    QVERIFY(!QFile::exists(crashed));
    QVERIFY(Autosave::leftBehind().empty());
}

void RecoveryTest::savingLeavesNothingBehind() {
    darkroom::test::TempDir dir;
    const QString path = QString::fromStdString(dir.file("pipeline.yaml"));
    darkroom::test::writeText(path.toStdString(), kPipeline);
    MainWindow w(guitest::registry(), {});
    QVERIFY(w.openPipeline(path));
    QVERIFY(w.document()->edit("colour map", [](darkroom::Graph& g) {
        g.setParameter("colour", "colormap", darkroom::Value("plasma"));
    }).isEmpty());
    w.autosave()->writeNow();
    const QString file = w.autosave()->file();
    QVERIFY(QFile::exists(file));
    QVERIFY(w.savePipeline(path));
    QVERIFY(!QFile::exists(file));
}

QTEST_MAIN(RecoveryTest)
#include "test_editor_recovery.moc"
