// TBB before any Qt header: Qt defines `emit` as a macro, a name TBB uses.
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include "layer_choice.h"

#include <darkroom/layer_blend.h>
#include <darkroom/layers.h>

#include <memory>
#include <vector>

namespace editor {
namespace {

using darkroom::Buffer;
namespace layers = darkroom::layers;

bool hasColour(const Buffer& b, int layers) {
    for (int k = 0; k < layers; ++k)
        for (const char* c : {"R", "G", "B"})
            if (!b.hostFloat(layers::channel(c, k))) return false;
    return true;
}

// The planes one layer contributes to the blend (a null alpha: opaque).
struct LayerPlanes {
    const float *r, *g, *b, *a, *z;
};

std::shared_ptr<darkroom::WritableBuffer> layerBuffer(const Buffer& b, int layer) {
    auto view = darkroom::makeHostBuffer(b.width(), b.height());
    view->metadata() = b.metadata();
    for (const auto& c : b.channels()) {
        auto [k, name] = layers::parse(c.name);
        if (k == layer) view->setPlane({name, c.type}, b.plane(c.name));
    }
    return view;
}

}  // namespace

QStringList layerChoices(const Buffer& b) {
    const int n = layers::count(b);
    if (n <= 1) return {};
    QStringList choices;
    if (hasColour(b, n)) choices << QStringLiteral("composite");
    choices << QStringLiteral("front");
    for (int k = 1; k < n; ++k) choices << QStringLiteral("layer %1").arg(k);
    return choices;
}

QString preferredLayerChoice(const QStringList& choices) {
    if (choices.isEmpty()) return {};
    return choices.front();  // "composite" when offered, else "front"
}

darkroom::BufferPtr layerView(const Buffer& b, int layer) { return layerBuffer(b, layer); }

darkroom::BufferPtr compositeView(const Buffer& b, int n) {
    std::vector<LayerPlanes> in;
    for (int k = 0; k < n; ++k)
        in.push_back({b.requireFloat(layers::channel("R", k)), b.requireFloat(layers::channel("G", k)),
                      b.requireFloat(layers::channel("B", k)), b.hostFloat(layers::channel("A", k)),
                      b.requireFloat(layers::channel("Z", k))});
    // The front layer's other channels (ids, scalars) stay, shared: the
    // probe then still says what is in front.
    auto view = layerBuffer(b, 0);
    const std::size_t pixels = b.pixelCount();
    float* dst[5];
    const char* names[5] = {"R", "G", "B", "A", "Z"};
    for (int c = 0; c < 5; ++c) {
        auto plane = darkroom::newHostPlane(pixels, false);
        dst[c] = static_cast<float*>(plane->writableData());
        view->setPlane({names[c]}, plane);
    }
    // Once per image, on the UI thread: rows split over the cores (a 2048²
    // image of four layers is 16 M surfaces).
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, pixels, 16384), [&](const auto& range) {
        std::vector<layers::Surface> s(in.size());
        for (std::size_t i = range.begin(); i < range.end(); ++i) {
            for (std::size_t k = 0; k < in.size(); ++k) {
                const LayerPlanes& p = in[k];
                s[k] = {p.z[i], p.r[i], p.g[i], p.b[i], p.a ? p.a[i] : 1.0f};
            }
            const layers::Blended c = layers::blendFrontToBack(s.data(), n);
            dst[0][i] = c.r, dst[1][i] = c.g, dst[2][i] = c.b, dst[3][i] = c.a, dst[4][i] = c.z;
        }
    });
    darkroom::sealPlanes(*view);
    return view;
}

darkroom::BufferPtr chooseLayer(const darkroom::BufferPtr& b, const QString& choice) {
    if (!b || choice.isEmpty()) return b;
    const int n = layers::count(*b);
    if (choice == QLatin1String("composite") && n > 1 && hasColour(*b, n)) return compositeView(*b, n);
    if (choice == QLatin1String("front")) return layerView(*b, 0);
    if (choice.startsWith(QLatin1String("layer "))) {
        bool ok = false;
        const int k = choice.mid(6).toInt(&ok);
        if (ok && k > 0 && k < n) return layerView(*b, k);
    }
    return b;
}

}  // namespace editor
