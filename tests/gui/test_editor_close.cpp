// Closing the editor with unsaved edits: the window asks, the edits are
// discarded, and the window goes without its parts calling back into it
// (issue 26, L5: the undo stack, cleared as the document went, told the
// half-destroyed window to update its title; UBSan reported the member call
// and Qt's debug build asserted).
#include "document.h"
#include "gui_support.h"
#include "main_window.h"

#include <QAbstractButton>
#include <QApplication>
#include <QMessageBox>
#include <QPointer>
#include <QTimer>
#include <QUndoStack>
#include <QtTest>

using editor::MainWindow;

class CloseTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { guitest::prepare(); }
    void closingWithUnsavedEditsCallsNothingOnTheGoingWindow();
};

void CloseTest::closingWithUnsavedEditsCallsNothingOnTheGoingWindow() {
    guitest::clearSettings();
    auto* w = new MainWindow(guitest::registry(), {});
    w->setAttribute(Qt::WA_DeleteOnClose);
    w->show();
    QVERIFY(QTest::qWaitForWindowExposed(w));
    QVERIFY(!w->addNode("ColorMapping").isEmpty());
    QVERIFY(!w->document()->undoStack()->isClean());
    QVERIFY(w->windowTitle().contains(" *"));

    // The title is the window's own (MainWindow::updateTitle). Once
    // ~MainWindow has run, the object is a mere QWidget: a title set then
    // comes from a call into a destroyed MainWindow.
    QStringList titlesAfterDestructor;
    connect(w, &QWidget::windowTitleChanged, this, [&titlesAfterDestructor, w](const QString& title) {
        if (!w->metaObject()->inherits(&MainWindow::staticMetaObject)) titlesAfterDestructor << title;
    });

    // "Save the changes first?" — Discard.
    bool asked = false;
    QTimer answer;
    answer.setInterval(20);
    connect(&answer, &QTimer::timeout, this, [&] {
        auto* box = qobject_cast<QMessageBox*>(QApplication::activeModalWidget());
        if (!box) return;
        asked = true;
        box->button(QMessageBox::Discard)->click();
    });
    answer.start();
    QPointer<MainWindow> alive(w);
    QVERIFY(w->close());
    answer.stop();
    QVERIFY(asked);
    QTRY_VERIFY_WITH_TIMEOUT(alive.isNull(), 10000);  // deleted on close
    QVERIFY2(titlesAfterDestructor.isEmpty(),
             qPrintable("MainWindow::updateTitle ran after ~MainWindow and set the title to: " +
                        titlesAfterDestructor.join(" | ")));
}

QTEST_MAIN(CloseTest)
#include "test_editor_close.moc"
