// One read path: the Cinema browser's entries and thumbnails come from the
// pipeline's CinemaReader, so every product it reads gets a thumbnail
// (.npz, .vti, composable image sets, not only what the image library
// reads), and choosing an entry feeds the reader what it needs to read it.
#include "cinema_entries.h"
#include "cinema_panel.h"
#include "document.h"
#include "gui_support.h"
#include "main_window.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/data/cinema/database.h>
#include <darkroom/data/cinema/writer.h>
#include <darkroom/core/evaluator.h>
#include <darkroom/core/graph.h>
#include <darkroom/data/formats/npy.h>
#include <darkroom/data/formats/vti.h>
#include <darkroom/data/image_io.h>

#include <QDir>
#include <QListWidget>
#include <QtTest>

using namespace darkroom;
using editor::MainWindow;

class CinemaTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void npzAndVtiEntriesGetThumbnails();
    void composableImageSetEntriesAreLayers();
    void anUnreadableEntrySaysWhy();
    void aDatabaseWrittenByCinemaWriterOpens();

private:
    bool thumbnailsArrived(int count);
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
};

void CinemaTest::initTestCase() {
    guitest::prepare();
    QVERIFY(guitest::registry().filter("CinemaReader"));
}

void CinemaTest::init() {
    dir_ = std::make_unique<test::TempDir>();
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
}

void CinemaTest::cleanup() {
    w_->document()->undoStack()->setClean();
    w_.reset();
    dir_.reset();
}

bool CinemaTest::thumbnailsArrived(int count) {
    QListWidget* list = w_->cinema()->thumbnails();
    return QTest::qWaitFor([&] {
        if (list->count() != count) return false;
        for (int i = 0; i < count; ++i)
            if (!list->item(i)->data(Qt::UserRole).toBool()) return false;  // still the stand-in
        return true;
    }, 30000);
}

void CinemaTest::npzAndVtiEntriesGetThumbnails() {
    // Two entries as .npz (a 2-D float member), two as TTK .vti.
    const std::string cdb = dir_->file("mixed.cdb");
    QDir().mkpath(QString::fromStdString(cdb));
    for (int t : {0, 1}) {
        NpyArray a;
        a.name = "elevation";
        a.descr = "<f4";
        a.shape = {12, 20};  // rows, columns
        for (int y = 0; y < 12; ++y)
            for (int x = 0; x < 20; ++x) a.values.push_back(float(x * (t + 1) + y));
        writeNpz(cdb + "/n" + std::to_string(t) + ".npz", {a});
        auto img = test::makeImage(20, 12, {"elevation"}, [t](int x, int y, int) { return float(x - y * t); });
        writeVti(cdb + "/v" + std::to_string(t) + ".vti", *img);
    }
    test::writeText(cdb + "/data.csv", "time,kind,FILE\n0,npz,n0.npz\n1,npz,n1.npz\n0,vti,v0.vti\n1,vti,v1.vti\n");
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    const auto& entries = w_->cinema()->entries();
    QCOMPARE(entries.size(), std::size_t(4));
    QCOMPARE(entries[2].parameters, QString("time=0, kind=vti"));
    QVERIFY(thumbnailsArrived(4));
    QCOMPARE(w_->cinema()->thumbnailFailures(), 0);
    // A thumbnail is the reader's output: the .npz ramp runs left to right.
    const QImage thumb = w_->cinema()->thumbnails()->item(0)->icon().pixmap(72, 72).toImage();
    QVERIFY(thumb.pixel(4, thumb.height() / 2) != thumb.pixel(thumb.width() - 5, thumb.height() / 2));
    // Choosing an entry drives the graph's CinemaReader with its row number.
    w_->cinema()->thumbnails()->setCurrentRow(3);
    const Node* reader = w_->document()->graph().node("cinemareader");
    QVERIFY(reader);
    QCOMPARE(reader->parameter("entry")->asInt(), 3);
    QVERIFY(!reader->parameter("parameters"));
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->image());
    QVERIFY(w_->renderView()->image()->hasChannel("elevation"));
    QCOMPARE(w_->renderView()->image()->width(), 20);
    QVERIFY(guitest::screenshot(w_.get(), "cinema-npz-vti"));
}

void CinemaTest::composableImageSetEntriesAreLayers() {
    const std::string cdb = test::sharedData("cinema/ttk_extracts_001.cdb");
    if (cdb.empty() || !QDir(QString::fromStdString(cdb)).exists()) QSKIP("../shared/data/cinema/ttk_extracts_001.cdb is absent");
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    // Six data.csv rows (three channels of two objects): two layers.
    const auto& entries = w_->cinema()->entries();
    QCOMPARE(entries.size(), std::size_t(2));
    QCOMPARE(entries[1].parameters, QString("CISImage=i000, CISLayer=l001"));
    QVERIFY(entries[1].label.contains("object=012"));
    QVERIFY(thumbnailsArrived(2));
    QCOMPARE(w_->cinema()->thumbnailFailures(), 0);
    // The browser's control is the object column, not the CIS columns.
    QVERIFY(w_->cinema()->control("object"));
    QVERIFY(!w_->cinema()->control("CISChannel"));
    w_->cinema()->thumbnails()->setCurrentRow(1);
    // The layer's first channel row: the reader reads the whole layer.
    QCOMPARE(w_->document()->graph().node("cinemareader")->parameter("entry")->asInt(),
             std::int64_t(entries[1].row));
    QVERIFY(guitest::waitIdle(*w_));
    const auto& img = w_->renderView()->image();
    QVERIFY(img);
    for (const char* c : {"Z", "Elevation", "SSSAO"}) QVERIFY2(img->hasChannel(c), c);
    QCOMPARE(img->width(), 1024);
    QVERIFY(guitest::screenshot(w_.get(), "cinema-composable"));
}

void CinemaTest::anUnreadableEntrySaysWhy() {
    const std::string cdb = dir_->file("broken.cdb");
    QDir().mkpath(QString::fromStdString(cdb));
    writeImage(*test::makeImage(8, 8, {"R", "G", "B"}, [](int, int, int) { return 0.5f; }), cdb + "/good.exr");
    test::writeText(cdb + "/bad.npz", "this is not a zip archive");
    test::writeText(cdb + "/data.csv", "theta,FILE\n0,good.exr\n30,bad.npz\n");
    QVERIFY(w_->openCinema(QString::fromStdString(cdb)));
    QVERIFY(QTest::qWaitFor([&] { return w_->cinema()->thumbnailFailures() == 1; }, 30000));
    QVERIFY(QTest::qWaitFor([&] { return w_->cinema()->thumbnails()->item(0)->data(Qt::UserRole).toBool(); }, 30000));
    QVERIFY2(w_->cinema()->thumbnails()->item(1)->toolTip().contains("bad.npz"),
             qPrintable(w_->cinema()->thumbnails()->item(1)->toolTip()));
}

void CinemaTest::aDatabaseWrittenByCinemaWriterOpens() {
    // A source database shaded into a PNG database by CinemaWriter, one
    // evaluation per row as `darkroom run --foreach` does, with a point list
    // beside each source entry: the browser lists the written entries with
    // the source's columns and a thumbnail each.
    const std::string source = dir_->file("source.cdb"), shaded = dir_->file("shaded.cdb");
    {
        CinemaWriterOptions o;
        o.attachments = {{"FILE_points", ".points.csv"}};
        CinemaWriter w(source, {"time", "phi"}, o);
        for (double t : {0.0, 1.0})
            for (double phi : {0.0, 90.0}) {
                auto img = test::makeImage(24, 16, {"Z", "R", "G", "B"}, [=](int x, int, int c) {
                    return c == 0 ? 2.0f : float(x) / 24.0f * float(t + 1) * 0.5f;
                });
                w.addEntry({{"time", CinemaValue(t)}, {"phi", CinemaValue(phi)}}, *img, {{"FILE_points", "x,y,z\n0,0,0\n"}});
            }
        w.finish();
    }
    {
        Graph g(guitest::registry());
        g.addNode("read", "CinemaReader");
        g.setParameter("read", "database", Value(source));
        g.addNode("write", "CinemaWriter");
        g.setParameter("write", "database", Value(shaded));
        g.connect({"read", "image"}, {"write", "image"});
        g.connect({"read", "row"}, {"write", "row"});
        Evaluator ev;
        const auto db = CinemaDatabase::open(source);
        for (std::size_t r = 0; r < db.rowCount(); ++r) {
            g.setParameter("read", "parameters", Value(db.formatParameters(r)));
            ev.run(g);
        }
    }
    QVERIFY(w_->openCinema(QString::fromStdString(shaded)));
    const auto& entries = w_->cinema()->entries();
    QCOMPARE(entries.size(), std::size_t(4));
    QCOMPARE(entries[3].parameters, QString("time=1, phi=90"));
    QVERIFY(thumbnailsArrived(4));
    QCOMPARE(w_->cinema()->thumbnailFailures(), 0);
    QVERIFY(w_->cinema()->control("time"));
    w_->cinema()->thumbnails()->setCurrentRow(2);
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->image());
    QCOMPARE(w_->renderView()->image()->width(), 24);
    QVERIFY(guitest::screenshot(w_.get(), "cinema-written"));
}

QTEST_MAIN(CinemaTest)
#include "test_editor_cinema.moc"
