// The render view on the GPU: every display mapping done by the shaders
// agrees with the CPU mapping (display.cpp, used for export and thumbnails)
// pixel by pixel; pan and zoom upload and map nothing; the pixel probe
// reads the buffer; a preview is drawn over the full image's area.
#include "display.h"
#include "gui_support.h"
#include "render_view.h"
#include "test_support.h"

#include <QSignalSpy>
#include <QtTest>

#include <cmath>
#include <limits>

using namespace darkroom;
using editor::RenderView;

namespace {

constexpr int kW = 40, kH = 24;

// Colour with alpha, depth with background, normals, a scalar with NaN, AO
// and integer ids: every kind of display mode.
BufferPtr testImage() {
    auto b = makeCpuBuffer(kW, kH, {{"R"}, {"G"}, {"B"}, {"A"}, {"Z"}, {"N.x"}, {"N.y"}, {"N.z"}, {"value"}, {"AO"},
                                    {"id", ChannelType::UInt32}});
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (int y = 0; y < kH; ++y)
        for (int x = 0; x < kW; ++x) {
            const std::size_t i = std::size_t(y) * kW + x;
            b->writeFloat("R")[i] = float(x) / (kW - 1);
            b->writeFloat("G")[i] = float(y) / (kH - 1);
            b->writeFloat("B")[i] = 0.002f * float(x);  // crosses sRGB's linear segment
            b->writeFloat("A")[i] = x < 4 ? 0.0f : x < 8 ? 0.5f : 1.0f;
            b->writeFloat("Z")[i] = (x + y) % 9 == 0 ? inf : 2.0f + 0.1f * float(x) + 0.05f * float(y);
            const float nx = std::cos(0.15f * float(x)), ny = std::sin(0.15f * float(x));
            b->writeFloat("N.x")[i] = (x == 5 && y == 5) ? nan : nx * 0.8f;
            b->writeFloat("N.y")[i] = ny * 0.8f;
            b->writeFloat("N.z")[i] = 0.6f;
            b->writeFloat("value")[i] = (x == 10 && y > 10) ? nan : std::sin(0.3f * float(x)) * float(y);
            b->writeFloat("AO")[i] = float((x * 7 + y * 3) % 17) / 16.0f;
            b->writeUInt("id")[i] = std::uint32_t(x / 10 + 4 * (y / 8));
        }
    return b;
}

// The checkerboard grey under framebuffer pixel (x, y), top-left origin.
int checker(int x, int y, int fbHeight) {
    const int gy = fbHeight - 1 - y;  // gl_FragCoord counts from the bottom
    return ((x / 8 + gy / 8) % 2 == 0) ? 150 : 100;
}

}  // namespace

class ViewTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void shaderMappingMatchesTheCpuMapping();
    void panAndZoomUploadNothing();
    void largeImageMappedAtTheShownSize();
    void probeReadsTheBuffer();
    void inputThroughTheNativeWindow();
    void previewCoversTheFullImageArea();

private:
    std::unique_ptr<RenderView> view_;
    BufferPtr image_;
};

void ViewTest::initTestCase() {
    QDir().mkpath(DARKROOM_GUI_ARTIFACTS);
    guitest::keepGlDriverLoaded();
    image_ = testImage();
}

void ViewTest::init() {
    view_ = std::make_unique<RenderView>();
    view_->resize(400, 300);
    view_->show();
    QVERIFY(QTest::qWaitForWindowExposed(view_.get()));
    view_->setImage(image_);
}

void ViewTest::cleanup() { view_.reset(); }

void ViewTest::shaderMappingMatchesTheCpuMapping() {
    QVERIFY2(view_->glError().isEmpty(), qPrintable(view_->glError()));
    const QStringList modes = view_->modes();
    QCOMPARE(modes.size(), 14);  // Colour, Depth Z, Vector N, 11 channels
    const QPoint at(17, 9);
    for (const QString& mode : modes) {
        view_->setMode(mode);
        view_->setView(1.0, at);
        const QImage fb = view_->grabFramebuffer().convertToFormat(QImage::Format_ARGB32);
        const QImage cpu = editor::renderDisplay(*image_, mode);
        int worst = 0;
        QPoint where;
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const QRgb c = cpu.pixel(x, y);
                const int a = qAlpha(c);
                const int under = checker(x + at.x(), y + at.y(), fb.height());
                auto over = [&](int v) { return int(std::lround((v * a + under * (255 - a)) / 255.0)); };
                const QRgb g = fb.pixel(x + at.x(), y + at.y());
                const int d = std::max({std::abs(qRed(g) - over(qRed(c))), std::abs(qGreen(g) - over(qGreen(c))),
                                        std::abs(qBlue(g) - over(qBlue(c)))});
                if (d > worst) worst = d, where = QPoint(x, y);
            }
        // Both round to 8 bits, the GPU once more when it blends: 2 levels.
        QVERIFY2(worst <= 2, qPrintable(QStringLiteral("%1: pixel %2,%3 differs by %4 levels")
                                            .arg(mode).arg(where.x()).arg(where.y()).arg(worst)));
        // Outside the image: the view's background.
        QCOMPARE(QColor(fb.pixel(at.x() + kW + 3, at.y() + 3)), QColor(30, 30, 32));
        fb.save(QStringLiteral(DARKROOM_GUI_ARTIFACTS "/view-%1.png").arg(QString(mode).replace(' ', '-')));
    }
}

void ViewTest::panAndZoomUploadNothing() {
    view_->setMode("Colour");
    view_->fit();
    const QImage before = view_->grabFramebuffer();  // draws
    const int uploads = view_->uploads(), mappings = view_->mappings();
    QCOMPARE(uploads, 4);  // R, G, B, A
    QCOMPARE(mappings, 1);
    QTest::mousePress(view_.get(), Qt::LeftButton, {}, QPoint(200, 150));
    QTest::mouseMove(view_.get(), QPoint(230, 170));
    QTest::mouseMove(view_.get(), QPoint(260, 190));
    QTest::mouseRelease(view_.get(), Qt::LeftButton, {}, QPoint(260, 190));
    QWheelEvent wheel(QPointF(100, 100), view_->mapToGlobal(QPointF(100, 100)), {}, QPoint(0, 240), Qt::NoButton,
                      Qt::NoModifier, Qt::NoScrollPhase, false);
    QCoreApplication::sendEvent(view_.get(), &wheel);
    const QImage after = view_->grabFramebuffer();
    QVERIFY(after != before);  // the picture moved and grew
    QCOMPARE(view_->uploads(), uploads);
    QCOMPARE(view_->mappings(), mappings);
    // Another mode maps again from the channels already uploaded where shared.
    view_->setMode("Depth Z");
    view_->grabFramebuffer();
    QCOMPARE(view_->mappings(), mappings + 1);
    QCOMPARE(view_->uploads(), uploads + 1);  // Z
}

void ViewTest::largeImageMappedAtTheShownSize() {
    // 1600 x 1200 in a 400 x 300 view: a quarter of each side is shown, so
    // every 4th pixel is mapped. Blocks of 40 x 40 pixels of one colour
    // each: the reduced mapping shows the CPU mapping's colour in each.
    constexpr int w = 1600, h = 1200, block = 40;
    auto big = test::makeImage(w, h, {"R", "G", "B"}, [](int x, int y, int c) {
        return c == 0 ? float(x / block) / (w / block) : c == 1 ? float(y / block) / (h / block) : 0.3f;
    });
    view_->setImage(big);
    view_->setMode("Colour");
    view_->fit();
    const QImage fb = view_->grabFramebuffer();
    QCOMPARE(view_->mappedLevel(), 2);
    const QImage cpu = editor::renderDisplay(*big, "Colour");
    const double zoom = view_->zoom();
    for (int by = 0; by < h / block; by += 7)
        for (int bx = 0; bx < w / block; bx += 5) {
            const QPointF centre((bx + 0.5) * block, (by + 0.5) * block);
            const QColor want(cpu.pixel(centre.toPoint())), got(fb.pixel((view_->offset() + centre * zoom).toPoint()));
            QVERIFY2(std::abs(want.red() - got.red()) <= 2 && std::abs(want.green() - got.green()) <= 2 &&
                         std::abs(want.blue() - got.blue()) <= 2,
                     qPrintable(QStringLiteral("block %1,%2: %3 against %4").arg(bx).arg(by).arg(got.name(), want.name())));
        }
    // Zoomed in to 1:1 the full image is mapped, once; then pan and zoom
    // map nothing again.
    const int mappings = view_->mappings(), uploads = view_->uploads();
    QTest::keyClick(view_.get(), Qt::Key_1);
    view_->grabFramebuffer();
    QCOMPARE(view_->mappings(), mappings + 1);
    QCOMPARE(view_->mappedLevel(), 0);
    view_->fit();
    view_->grabFramebuffer();
    view_->setView(2.0, QPointF(-100, -50));
    view_->grabFramebuffer();
    QCOMPARE(view_->mappings(), mappings + 1);
    QCOMPARE(view_->uploads(), uploads);
}

void ViewTest::probeReadsTheBuffer() {
    view_->setView(4.0, QPointF(10, 10));
    QSignalSpy spy(view_.get(), &RenderView::probed);
    QTest::mouseMove(view_.get(), QPoint(10 + 4 * 3 + 2, 10 + 4 * 2 + 1));  // pixel (3, 2)
    QVERIFY(!spy.isEmpty());
    const QString text = spy.last().at(0).toString();
    QVERIFY2(text.startsWith("x 3, y 2 |"), qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral(" R %1 ").arg(3.0 / 39.0, 0, 'g', 6)), qPrintable(text));
    QVERIFY2(text.contains(" id 0"), qPrintable(text));
}

void ViewTest::inputThroughTheNativeWindow() {
    // Events as the window system delivers them, to the native window the
    // frames are drawn into: they pan, zoom and probe as on the widget.
    QWindow* window = view_->surface();
    QVERIFY(QTest::qWaitForWindowExposed(window));
    QCOMPARE(window->size(), view_->size());
    view_->setView(4.0, QPointF(10, 10));
    QSignalSpy probed(view_.get(), &RenderView::probed);
    QTest::mouseMove(window, QPoint(10 + 4 * 3 + 2, 10 + 4 * 2 + 1));  // pixel (3, 2)
    QTRY_VERIFY(!probed.isEmpty());
    QVERIFY2(probed.last().at(0).toString().startsWith("x 3, y 2 |"), qPrintable(probed.last().at(0).toString()));
    QTest::mousePress(window, Qt::LeftButton, {}, QPoint(100, 100));
    QTest::mouseMove(window, QPoint(130, 120));
    QTest::mouseRelease(window, Qt::LeftButton, {}, QPoint(130, 120));
    QCOMPARE(view_->offset(), QPointF(40, 30));
    QTest::keyClick(window, Qt::Key_1);
    QCOMPARE(view_->zoom(), 1.0);
    // Frames reach the screen: the swap is announced.
    QSignalSpy swapped(view_.get(), &RenderView::frameSwapped);
    view_->requestFrame();
    QVERIFY(swapped.wait(5000));
}

void ViewTest::previewCoversTheFullImageArea() {
    view_->fit();
    const double zoom = view_->zoom();
    const QPointF offset = view_->offset();
    // A quarter-size preview of the same picture (a 10 x 6 image, level 2).
    auto small = test::makeImage(kW / 4, kH / 4, {"R", "G", "B"}, [](int, int, int c) { return c == 0 ? 1.0f : 0.0f; });
    view_->setImage(small, 2);
    QCOMPARE(view_->zoom(), zoom);  // the view did not jump
    QCOMPARE(view_->offset(), offset);
    const QImage fb = view_->grabFramebuffer();
    // The preview's red fills the full image's area, to its far corner.
    const QPoint corner = (offset + QPointF(kW, kH) * zoom - QPointF(2, 2)).toPoint();
    QCOMPARE(QColor(fb.pixel(corner)), QColor(255, 0, 0));
    QCOMPARE(QColor(fb.pixel((offset + QPointF(2, 2)).toPoint())), QColor(255, 0, 0));
    QSignalSpy spy(view_.get(), &RenderView::probed);
    QTest::mouseMove(view_.get(), corner);
    QVERIFY(!spy.isEmpty());
    QVERIFY2(spy.last().at(0).toString().startsWith("preview 1/4: x 9, y 5"), qPrintable(spy.last().at(0).toString()));
    fb.save(QStringLiteral(DARKROOM_GUI_ARTIFACTS "/view-preview.png"));
}

QTEST_MAIN(ViewTest)
#include "test_editor_view.moc"
