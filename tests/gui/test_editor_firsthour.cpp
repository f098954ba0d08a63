// The first hour of a new user, without friction: each behaviour a new user
// tripped over has its test here.
//  - a channel port lists the input's channels (free text still allowed);
//  - the Cinema browser's labels and sliders show values readably;
//  - an evaluation error is written over the render view, naming the node;
//  - a node just added, without inputs, is waiting for input, not failed;
//  - after a crash only the session that crashed is offered back;
//  - a Help menu with the documentation and the keyboard shortcuts;
//  - `darkroom-editor --help` prints its usage without a display.
#include "autosave.h"
#include "cinema_panel.h"
#include "document.h"
#include "graph_scene.h"
#include "gui_support.h"
#include "main_window.h"
#include "node_item.h"
#include "param_widget.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/data/image_io.h>
#include <darkroom/core/pipeline.h>

#include <QAbstractItemView>
#include <QComboBox>
#include <QDockWidget>
#include <QDir>
#include <QFile>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QProcess>
#include <QSlider>
#include <QTextBrowser>
#include <QtTest>

#include <memory>

using namespace darkroom;
using editor::MainWindow;

namespace {

const char* kFields = R"(darkroom: 1
nodes:
  read:
    type: ImageReader
    parameters:
      path: fields.exr
  colour:
    type: ColorMapping
edges:
  - read.image -> colour.image
)";

const char* kMissing = R"(darkroom: 1
nodes:
  read:
    type: ImageReader
    parameters:
      path: nowhere.exr
  colour:
    type: ColorMapping
edges:
  - read.image -> colour.image
)";

// The pid of a process that has ended.
qint64 deadPid() {
    QProcess p;
    p.start("true", {});
    p.waitForFinished();
    return p.processId() > 0 ? p.processId() : 999999;
}

}  // namespace

class FirstHourTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void channelPortListsTheInputsChannels();
    void cinemaLabelsAndSlidersShowReadableValues();
    void evaluationErrorIsShownInTheRenderView();
    void nodeAddedWithoutInputsIsWaiting();
    void onlyTheSessionThatCrashedIsOfferedBack();
    void helpMenuHasTheDocsAndTheShortcuts();
    void helpPrintsUsageWithoutADisplay();

private:
    QString write(const char* name, const char* text);
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
};

void FirstHourTest::initTestCase() { guitest::prepare(); }

void FirstHourTest::init() {
    dir_ = std::make_unique<test::TempDir>();
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
}

void FirstHourTest::cleanup() {
    w_->document()->undoStack()->setClean();
    w_.reset();
    dir_.reset();
}

QString FirstHourTest::write(const char* name, const char* text) {
    test::writeText(dir_->file(name), text);
    return QString::fromStdString(dir_->file(name));
}

void FirstHourTest::channelPortListsTheInputsChannels() {
    writeImage(*test::makeImage(16, 8, {"pressure", "temperature", "Z"}, [](int x, int y, int c) {
        return float(x + y * c);
    }), dir_->file("fields.exr"));
    QVERIFY(w_->openPipeline(write("p.yaml", kFields)));
    w_->scene()->nodeItem("colour")->setSelected(true);
    QVERIFY(guitest::waitIdle(*w_));
    editor::ParamWidget* pw = w_->scene()->nodeItem("colour")->paramWidget("channel");
    QVERIFY(pw);
    auto* combo = pw->findChild<QComboBox*>();
    QVERIFY2(combo, "the channel port has no drop-down");
    QTRY_VERIFY_WITH_TIMEOUT(combo->count() >= 3, 10000);
    QStringList items;
    for (int i = 0; i < combo->count(); ++i) items << combo->itemText(i);
    for (const char* c : {"pressure", "temperature", "Z"}) QVERIFY2(items.contains(c), qPrintable(items.join(",")));
    QVERIFY(combo->isEditable());  // free text is still allowed
    QVERIFY(guitest::screenshot(w_.get(), "firsthour-channel-port"));
    combo->showPopup();
    QTest::qWait(400);
    QVERIFY(guitest::screenshot(combo->view()->window(), "firsthour-channel-dropdown"));
    combo->hidePopup();

    // Choosing an item sets the port.
    combo->setCurrentIndex(int(items.indexOf("temperature")));
    emit combo->textActivated(QStringLiteral("temperature"));
    QCOMPARE(w_->document()->graph().node("colour")->parameter("channel")->asString(), std::string("temperature"));
    // Typing a name the input does not have (yet) is allowed too.
    combo->lineEdit()->setFocus();
    combo->lineEdit()->selectAll();
    QTest::keyClicks(combo->lineEdit(), "velocity");
    QTest::keyClick(combo->lineEdit(), Qt::Key_Return);
    QCOMPARE(w_->document()->graph().node("colour")->parameter("channel")->asString(), std::string("velocity"));
    QVERIFY(guitest::waitIdle(*w_));
}

void FirstHourTest::cinemaLabelsAndSlidersShowReadableValues() {
    // Values as a simulation code writes them: %E with six decimals.
    const std::string cdb = dir_->file("sim.cdb");
    QDir().mkpath(QString::fromStdString(cdb));
    for (int i = 0; i < 4; ++i)
        writeImage(*test::makeImage(8, 8, {"R", "G", "B"}, [i](int, int, int) { return i / 3.0f; }),
                   cdb + "/e" + std::to_string(i) + ".exr");
    // The last time is a sum of steps written with its binary noise.
    test::writeText(cdb + "/data.csv", "time,kind,run,FILE\n0.000000E+00,a,007,e0.exr\n2.500000E-01,a,008,e1.exr\n"
                                       "0.44999999999999996,b,009,e2.exr\n1.250000E+03,b,010,e3.exr\n");
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    QListWidget* list = w_->cinema()->thumbnails();
    QCOMPARE(list->count(), 4);
    // Integers stay as written: a padded run number is an identifier.
    QCOMPARE(list->item(0)->text(), QString("time=0, kind=a, run=007"));
    QCOMPARE(list->item(1)->text(), QString("time=0.25, kind=a, run=008"));
    QCOMPARE(list->item(2)->text(), QString("time=0.45, kind=b, run=009"));
    QCOMPARE(list->item(3)->text(), QString("time=1250, kind=b, run=010"));
    // The reader still gets the values as written (they find the row exactly).
    QCOMPARE(w_->cinema()->entries()[1].parameters, QString("time=2.500000E-01, kind=a, run=008"));

    // The slider shows its value beside it, and follows a chosen entry.
    auto* slider = qobject_cast<QSlider*>(w_->cinema()->control("time"));
    QVERIFY(slider);
    auto* value = w_->cinema()->findChild<QLabel*>("value:time");
    QVERIFY2(value, "the time slider has no value label");
    QCOMPARE(value->text(), QString("0"));
    slider->setValue(1);
    QCOMPARE(value->text(), QString("0.25"));
    list->setCurrentRow(2);
    QCOMPARE(value->text(), QString("0.45"));
    QCOMPARE(w_->cinema()->findChild<QLabel*>("value:run")->text(), QString("009"));
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(guitest::screenshot(w_->dock("cinema"), "firsthour-cinema-values"));
}

void FirstHourTest::evaluationErrorIsShownInTheRenderView() {
    QVERIFY(w_->openPipeline(write("missing.yaml", kMissing)));
    QVERIFY(guitest::waitIdle(*w_));
    const QString m = w_->renderView()->message();
    QVERIFY2(m.contains("read") && m.contains("nowhere.exr"), qPrintable(m));
    QVERIFY(w_->renderView()->messageIsError());
    // Written over the view: the banner's red is on screen.
    const QImage shot = w_->renderView()->grabFramebuffer();
    int red = 0;
    for (int x = 0; x < shot.width(); x += 4) {
        const QColor c = shot.pixelColor(x, 12);
        red += c.red() > 120 && c.green() < 90 && c.blue() < 90;
    }
    QVERIFY2(red > shot.width() / 16, qPrintable(QString::number(red)));
    QVERIFY(guitest::screenshot(w_.get(), "firsthour-error-in-view"));
    // Mending the input clears it.
    writeImage(*test::makeImage(8, 8, {"value"}, [](int x, int, int) { return float(x); }), dir_->file("nowhere.exr"));
    QVERIFY(w_->document()->edit("touch", [](Graph& g) { g.setParameter("colour", "colormap", Value("inferno")); }).isEmpty());
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->image());
    QVERIFY2(w_->renderView()->message().isEmpty(), qPrintable(w_->renderView()->message()));
}

void FirstHourTest::nodeAddedWithoutInputsIsWaiting() {
    const QString name = w_->addNode("ColorMapping");
    QCOMPARE(name, QString("colormapping"));
    QVERIFY(guitest::waitIdle(*w_));
    editor::NodeItem* item = w_->scene()->nodeItem(name);
    QVERIFY(item);
    QVERIFY2(!item->failed(), qPrintable(item->toolTip()));
    QVERIFY(item->waiting());
    QVERIFY2(item->badgeText() == "waiting for input", qPrintable(item->badgeText()));
    QVERIFY2(w_->frameText().contains("waiting for input"), qPrintable(w_->frameText()));
    QVERIFY2(!w_->frameText().contains("failed"), qPrintable(w_->frameText()));
    QVERIFY(!w_->renderView()->messageIsError());
    QVERIFY2(w_->renderView()->message().contains("waiting for input"), qPrintable(w_->renderView()->message()));
    QVERIFY(guitest::screenshot(w_.get(), "firsthour-waiting"));
    // Once its input is connected it runs.
    writeImage(*test::makeImage(8, 8, {"value"}, [](int x, int, int) { return float(x); }), dir_->file("v.exr"));
    QVERIFY(w_->document()->edit("connect", [&](Graph& g) {
        g.addNode("read", "ImageReader");
        g.setParameter("read", "path", Value(dir_->file("v.exr")));
        g.connect({"read", "image"}, {name.toStdString(), "image"});
    }).isEmpty());
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->image());
    QVERIFY(!item->waiting());
    QVERIFY(!item->failed());
}

void FirstHourTest::onlyTheSessionThatCrashedIsOfferedBack() {
    // Three sessions ended without a clean exit, the newest last: only it
    // is asked about; the older ones are set aside, not lost, and listed
    // under File > Recover.
    QDir().mkpath(editor::Autosave::folder());
    QStringList files;
    for (int i = 0; i < 3; ++i) {
        const QString f = editor::Autosave::folder() + "/" + QString::number(deadPid() + 100000 * (i + 1)) + ".yaml";
        QFile out(f);
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(("# darkroom-editor autosave of: /tmp/session" + std::to_string(i) + ".yaml\n").c_str());
        out.write(kFields);
        // Qt sets a file's time only while it is open, and a later flush
        // would stamp it "now" again: all three got the same time, and the
        // order was left to chance.
        QVERIFY(out.flush());
        QVERIFY(out.setFileTime(QDateTime::currentDateTime().addSecs(-600 + 60 * i), QFileDevice::FileModificationTime));
        out.close();
        files << f;
    }
    QStringList asked;
    w_->offerRecovery([&](const editor::Recovery& r) {
        asked << r.originalPath;
        return false;  // the user declines
    });
    QCOMPARE(asked, QStringList{"/tmp/session2.yaml"});
    QVERIFY(!QFile::exists(files[2]));  // declined: dropped
    const auto aside = editor::Autosave::setAside();
    QCOMPARE(int(aside.size()), 2);
    QCOMPARE(aside[0].originalPath, QString("/tmp/session1.yaml"));
    QVERIFY(editor::Autosave::leftBehind().empty());
    // The next start asks nothing.
    asked.clear();
    w_->offerRecovery([&](const editor::Recovery& r) {
        asked << r.originalPath;
        return true;
    });
    QVERIFY(asked.isEmpty());
    // The set-aside sessions can still be restored from the File menu.
    QMenu* recover = w_->findChild<QMenu*>("recoverMenu");
    QVERIFY(recover);
    w_->updateRecoverMenu();
    QCOMPARE(recover->actions().size(), 2);
    QVERIFY(recover->actions()[1]->text().contains("session0"));
    recover->actions()[0]->trigger();
    QCOMPARE(w_->document()->path(), QString("/tmp/session1.yaml"));
    QVERIFY(w_->document()->graph().node("colour"));
    QCOMPARE(int(editor::Autosave::setAside().size()), 1);
    for (const auto& r : editor::Autosave::setAside()) editor::Autosave::drop(r);
}

void FirstHourTest::helpMenuHasTheDocsAndTheShortcuts() {
    QMenu* help = nullptr;
    for (QAction* a : w_->menuBar()->actions())
        if (a->text().remove('&') == "Help") help = a->menu();
    QVERIFY2(help, "no Help menu");
    QAction *docs = nullptr, *keys = nullptr;
    for (QAction* a : help->actions()) {
        const QString t = a->text().remove('&');
        if (t.startsWith("Documentation")) docs = a;
        if (t.startsWith("Keyboard shortcuts")) keys = a;
    }
    QVERIFY(docs && keys);
    docs->trigger();
    auto* browser = w_->findChild<QTextBrowser*>("helpDocs");
    QVERIFY(browser);
    QTRY_VERIFY(browser->isVisible());
    QVERIFY2(browser->toPlainText().contains("The node graph"), qPrintable(browser->toPlainText().left(200)));
    QVERIFY(guitest::screenshot(browser->window(), "firsthour-help-docs"));
    keys->trigger();
    auto* table = w_->findChild<QTextBrowser*>("helpShortcuts");
    QVERIFY(table);
    QTRY_VERIFY(table->isVisible());
    const QString text = table->toPlainText();
    for (const char* k : {"Tab", "Ctrl+Z", "Ctrl+S", "Delete", "F"}) QVERIFY2(text.contains(k), k);
    QVERIFY(guitest::screenshot(table->window(), "firsthour-help-shortcuts"));
    browser->window()->close();
    table->window()->close();
}

void FirstHourTest::helpPrintsUsageWithoutADisplay() {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY", "QT_QPA_PLATFORM"}) env.remove(v);
    for (const char* flag : {"--help", "-h"}) {
        QProcess p;
        p.setProcessEnvironment(env);
        p.start(QStringLiteral(DARKROOM_EDITOR_EXE), {flag});
        QVERIFY(p.waitForFinished(20000));
        const QString out = QString::fromUtf8(p.readAllStandardOutput());
        QVERIFY2(p.exitStatus() == QProcess::NormalExit && p.exitCode() == 0,
                 qPrintable(out + QString::fromUtf8(p.readAllStandardError())));
        QVERIFY2(out.contains("Usage: darkroom-editor") && out.contains(".cdb") && out.contains(".yaml"), qPrintable(out));
    }
    // An unknown option is bad usage (exit 2), also without a display.
    QProcess p;
    p.setProcessEnvironment(env);
    p.start(QStringLiteral(DARKROOM_EDITOR_EXE), {"--frobnicate"});
    QVERIFY(p.waitForFinished(20000));
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(QString::fromUtf8(p.readAllStandardError()).contains("--frobnicate"));
}

QTEST_MAIN(FirstHourTest)
#include "test_editor_firsthour.moc"
