// The editor opens a database written in situ (darkroom/insitu.h): its
// Cinema browser offers the time and camera columns, every entry gets a
// thumbnail, and an entry's G-buffer reaches the view with its channels.
#include "cinema_panel.h"
#include "document.h"
#include "gui_support.h"
#include "main_window.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/insitu.h>

#include <QListWidget>
#include <QtTest>

#include <cmath>

using namespace darkroom;
using editor::MainWindow;

class InSituTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { guitest::prepare(); }
    void aTimeVaryingInSituDatabaseOpensAndShows();
};

void InSituTest::aTimeVaryingInSituDatabaseOpensAndShows() {
    test::TempDir dir;
    const std::string cdb = dir.file("heat.cdb");
    // A 12 x 12 height field, two time steps, two azimuths.
    constexpr int n = 12;
    std::vector<float> vertices(4 * n * n), height(n * n);
    std::vector<std::uint32_t> triangles;
    for (int j = 0; j + 1 < n; ++j)
        for (int i = 0; i + 1 < n; ++i) {
            const std::uint32_t v = std::uint32_t(j * n + i);
            triangles.insert(triangles.end(), {v, v + 1, v + n + 1, v, v + n + 1, v + n});
        }
    darkroom_insitu* s = darkroom_insitu_open(cdb.c_str(), DARKROOM_INSITU_CREATE);
    const double target[3] = {0, 0, 0}, up[3] = {0, 0, 1}, phi[2] = {0, 45}, theta[1] = {40};
    QCOMPARE(darkroom_insitu_set_image(s, 64, 64, 30.0, 0.0), int(DARKROOM_INSITU_OK));
    QCOMPARE(darkroom_insitu_camera_orbit(s, target, 4.6, up, phi, 2, theta, 1), int(DARKROOM_INSITU_OK));
    QCOMPARE(darkroom_insitu_request_field(s, "height"), int(DARKROOM_INSITU_OK));
    for (int step = 0; step < 2; ++step) {
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const float x = -1.0f + 2.0f * float(i) / (n - 1), y = -1.0f + 2.0f * float(j) / (n - 1);
                const float z = 0.3f * std::sin(3.0f * x + float(step)) * std::cos(2.0f * y);
                float* v = &vertices[4 * std::size_t(j * n + i)];
                v[0] = x, v[1] = y, v[2] = z, v[3] = 0.0f;
                height[std::size_t(j * n + i)] = z;
            }
        QCOMPARE(darkroom_insitu_begin_step(s, 0.5 * step), int(DARKROOM_INSITU_OK));
        QCOMPARE(darkroom_insitu_triangles(s, "plate", vertices.data(), 16, n * n, triangles.data(),
                                           std::int64_t(triangles.size() / 3)),
                 int(DARKROOM_INSITU_OK));
        QCOMPARE(darkroom_insitu_field(s, "plate", "height", height.data(), n * n, DARKROOM_INSITU_POINT_DATA),
                 int(DARKROOM_INSITU_OK));
        QVERIFY2(darkroom_insitu_capture(s) == DARKROOM_INSITU_OK, darkroom_insitu_error(s));
    }
    QCOMPARE(darkroom_insitu_close(s), int(DARKROOM_INSITU_OK));

    MainWindow w(guitest::registry(), Diagnostics{});
    w.show();
    QVERIFY(QTest::qWaitForWindowExposed(&w));
    QVERIFY(w.openCinema(QString::fromStdString(cdb)));
    QCOMPARE(w.cinema()->entries().size(), std::size_t(4));
    for (const char* column : {"time", "phi", "theta"}) QVERIFY2(w.cinema()->control(column), column);
    QListWidget* list = w.cinema()->thumbnails();
    QVERIFY(QTest::qWaitFor([&] {
        for (int i = 0; i < list->count(); ++i)
            if (!list->item(i)->data(Qt::UserRole).toBool()) return false;  // still the stand-in
        return list->count() == 4;
    }, 30000));
    QCOMPARE(w.cinema()->thumbnailFailures(), 0);
    list->setCurrentRow(3);
    QCOMPARE(w.document()->graph().node("cinemareader")->parameter("entry")->asInt(), 3);
    QVERIFY(guitest::waitIdle(w));
    const auto& image = w.renderView()->image();
    QVERIFY(image);
    QVERIFY(image->hasChannel("Z"));
    QVERIFY(image->hasChannel("height"));
    QCOMPARE(image->width(), 64);
    QVERIFY(guitest::screenshot(&w, "insitu-database"));
    w.document()->undoStack()->setClean();
}

QTEST_MAIN(InSituTest)
#include "test_editor_insitu.moc"
