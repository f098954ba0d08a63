// A layered buffer in the editor (issue 30): the layer chooser beside the
// Show chooser lists the composite, the front layer and every deeper layer;
// a layer is shown under the plain channel names (so the mode chooser
// applies to it), the composite is the front-to-back blend of the colour
// layers; an ordinary buffer hides the chooser and is shown as it is.
#include "gui_support.h"
#include "layer_choice.h"
#include "main_window.h"
#include "render_view.h"
#include "test_support.h"

#include <darkroom/data/image_io.h>
#include <darkroom/layers.h>
#include <darkroom/srgb.h>

#include <QComboBox>
#include <QtTest>

#include <cmath>
#include <limits>
#include <memory>

using namespace darkroom;
using editor::MainWindow;
using editor::RenderView;

namespace {

constexpr int kW = 48, kH = 32;

// Three layers of constant colour and depth: red, then green, each half
// transparent, then opaque blue, which only the left half of the image has
// (the right half's rays cross two surfaces: layer 2 missing there).
struct Layer {
    float r, g, b, a, z;
};
constexpr Layer kLayers[3] = {{1, 0, 0, 0.5f, 2}, {0, 1, 0, 0.5f, 3}, {0, 0, 1, 1, 4}};

BufferPtr layeredImage(int layerCount = 3) {
    std::vector<ChannelDesc> channels;
    for (int k = 0; k < layerCount; ++k)
        for (const char* c : {"R", "G", "B", "A", "Z"}) channels.emplace_back(layers::channel(c, k));
    auto b = makeCpuBuffer(kW, kH, channels);
    const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
    for (int k = 0; k < layerCount; ++k) {
        const Layer& l = kLayers[k];
        for (int y = 0; y < kH; ++y)
            for (int x = 0; x < kW; ++x) {
                const std::size_t i = std::size_t(y) * kW + x;
                const bool missing = k == 2 && x >= kW / 2;
                b->writeFloat(layers::channel("R", k))[i] = missing ? nan : l.r;
                b->writeFloat(layers::channel("G", k))[i] = missing ? nan : l.g;
                b->writeFloat(layers::channel("B", k))[i] = missing ? nan : l.b;
                b->writeFloat(layers::channel("A", k))[i] = missing ? nan : l.a;
                b->writeFloat(layers::channel("Z", k))[i] = missing ? inf : l.z;
            }
    }
    return b;
}

// The blend written out: C = sum a_k c_k prod_{j<k} (1 - a_j), straight C / A.
// Left: 0.5 red + 0.25 green + 0.25 blue, A = 1; right: no blue, A = 0.75.
constexpr float kLeft[4] = {0.5f, 0.25f, 0.25f, 1.0f};
constexpr float kRight[4] = {0.5f / 0.75f, 0.25f / 0.75f, 0.0f, 0.75f};

const char* kPipeline = R"(darkroom: 1
nodes:
  read:
    type: ImageReader
    parameters:
      path: layered.exr
  write:
    type: ImageWriter
    parameters:
      path: out.exr
edges:
  - read.image -> write.image
)";

}  // namespace

class LayersTest : public QObject {
    Q_OBJECT
private slots:
    void initTestCase();
    void init();
    void cleanup();
    void chooserListsTheLayersOfALayeredImage();
    void layerChoiceDrivesTheShownChannels();
    void compositeIsTheFrontToBackBlend();
    void choiceKeptWhenReEvaluated();
    void oneLayerHidesTheChooser();

private:
    QComboBox* chooser() const { return w_->findChild<QComboBox*>("layerChooser"); }
    void openLayered();
    // The framebuffer's colour at image pixel (x, y), the view at 1:1.
    QColor shown(int x, int y);
    std::unique_ptr<test::TempDir> dir_;
    std::unique_ptr<MainWindow> w_;
};

void LayersTest::initTestCase() { guitest::prepare(); }

void LayersTest::init() {
    dir_ = std::make_unique<test::TempDir>();
    w_ = std::make_unique<MainWindow>(guitest::registry(), Diagnostics{});
    w_->show();
    QVERIFY(QTest::qWaitForWindowExposed(w_.get()));
}

void LayersTest::cleanup() {
    w_.reset();
    dir_.reset();
}

void LayersTest::openLayered() {
    // Through a file and a reader, as a layered capture reaches the editor.
    writeImage(*layeredImage(), dir_->file("layered.exr"));
    test::writeText(dir_->file("p.yaml"), kPipeline);
    QVERIFY(w_->openPipeline(QString::fromStdString(dir_->file("p.yaml"))));
    QVERIFY(guitest::waitIdle(*w_));
    QVERIFY(w_->renderView()->sourceImage());
    QCOMPARE(layers::count(*w_->renderView()->sourceImage()), 3);
}

QColor LayersTest::shown(int x, int y) {
    RenderView* view = w_->renderView();
    view->setView(1.0, QPointF(20, 20));
    const QImage fb = view->grabFramebuffer();
    return QColor(fb.pixel(20 + x, 20 + y));
}

void LayersTest::chooserListsTheLayersOfALayeredImage() {
    openLayered();
    QVERIFY(chooser()->isVisible());
    QStringList items;
    for (int i = 0; i < chooser()->count(); ++i) items << chooser()->itemText(i);
    QCOMPARE(items, QStringList({"composite", "front", "layer 1", "layer 2"}));
    QCOMPARE(chooser()->currentText(), QString("composite"));  // the picture the layers make
    // The modes are those of one layer: no "Channel layer1.Z".
    QVERIFY(!w_->renderView()->modes().contains("Channel layer1.Z"));
    QCOMPARE(w_->renderView()->mode(), QString("Colour"));
    QVERIFY(guitest::screenshot(w_.get(), "layers-composite"));
}

void LayersTest::layerChoiceDrivesTheShownChannels() {
    openLayered();
    RenderView* view = w_->renderView();
    chooser()->setCurrentText("layer 1");
    QCOMPARE(view->layerChoice(), QString("layer 1"));
    QCOMPARE(view->image()->hostFloat("Z")[0], 3.0f);
    // Shared, not copied: the layer's planes are the source's.
    QCOMPARE(view->image()->plane("G").get(), view->sourceImage()->plane("layer1.G").get());
    // Half-transparent green over the checkerboard.
    const QColor g = shown(3, 3);
    QVERIFY2(g.red() == g.blue() && g.green() > g.red() + 60, qPrintable(g.name()));
    // The mode chooser applies to the chosen layer: Depth Z of layer 2 has
    // its left half (depth 4) and a transparent right half.
    view->setMode("Channel Z");
    chooser()->setCurrentText("layer 2");
    QCOMPARE(view->mode(), QString("Channel Z"));
    QCOMPARE(view->image()->hostFloat("Z")[0], 4.0f);
    QVERIFY(std::isinf(view->image()->hostFloat("Z")[kW - 1]));
    chooser()->setCurrentText("front");
    QCOMPARE(view->image()->hostFloat("Z")[0], 2.0f);
    QVERIFY(!view->image()->hasChannel("layer1.Z"));
    view->setMode("Colour");
    const QColor r = shown(3, 3);
    QVERIFY2(r.green() == r.blue() && r.red() > r.green() + 60, qPrintable(r.name()));
    view->fit();
    QVERIFY(guitest::screenshot(w_.get(), "layers-front"));
}

void LayersTest::compositeIsTheFrontToBackBlend() {
    openLayered();
    RenderView* view = w_->renderView();
    QCOMPARE(view->layerChoice(), QString("composite"));
    const BufferPtr& c = view->image();
    const char* names[4] = {"R", "G", "B", "A"};
    for (int ch = 0; ch < 4; ++ch) {
        QVERIFY(std::abs(c->hostFloat(names[ch])[0] - kLeft[ch]) < 1e-6f);
        QVERIFY(std::abs(c->hostFloat(names[ch])[kW - 1] - kRight[ch]) < 1e-6f);
    }
    QCOMPARE(c->hostFloat("Z")[kW - 1], 2.0f);  // the nearest surface that shows
    // On screen: the blend sRGB-encoded, the right half over the checkerboard.
    auto byte = [](float v) { return int(std::lround(255.0f * linearToSrgb(v))); };
    const QColor left = shown(3, 3);
    QVERIFY2(std::abs(left.red() - byte(kLeft[0])) <= 2 && std::abs(left.green() - byte(kLeft[1])) <= 2 &&
                 std::abs(left.blue() - byte(kLeft[2])) <= 2,
             qPrintable(left.name()));
    const QColor right = shown(kW - 4, 3);
    QVERIFY2(right.blue() > 0 && right.red() > right.green() && right.green() > right.blue(),
             qPrintable(right.name()));
    view->fit();
    QVERIFY(guitest::screenshot(w_.get(), "layers-composite-blend"));
}

void LayersTest::choiceKeptWhenReEvaluated() {
    openLayered();
    RenderView* view = w_->renderView();
    chooser()->setCurrentText("layer 1");
    // A new frame with the same layers (an edit upstream): the choice stays.
    view->setImage(layeredImage());
    QCOMPARE(view->layerChoice(), QString("layer 1"));
    QCOMPARE(chooser()->currentText(), QString("layer 1"));
    QCOMPARE(view->image()->hostFloat("Z")[0], 3.0f);
    // Two layers still have layer 1; one layer has none.
    view->setImage(layeredImage(2));
    QCOMPARE(chooser()->currentText(), QString("layer 1"));
    QCOMPARE(chooser()->count(), 3);
    view->setImage(layeredImage(1));
    QVERIFY(!chooser()->isVisible());
    QVERIFY(view->layerChoices().isEmpty());
}

void LayersTest::oneLayerHidesTheChooser() {
    openLayered();
    QVERIFY(chooser()->isVisible());
    // An ordinary buffer: no chooser, and it is shown as it is (no view built).
    auto plain = test::makeImage(kW, kH, {"R", "G", "B", "Z"}, [](int, int, int c) { return c == 3 ? 2.0f : 0.5f; });
    w_->renderView()->setImage(plain);
    QVERIFY(!chooser()->isVisible());
    QCOMPARE(w_->renderView()->image().get(), plain.get());
    QVERIFY(editor::layerChoices(*plain).isEmpty());
    QVERIFY(guitest::screenshot(w_.get(), "layers-one-layer"));
}

QTEST_MAIN(LayersTest)
#include "test_editor_layers.moc"
