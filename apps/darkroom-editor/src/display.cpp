#include "display.h"

#include <darkroom/colormap.h>
#include <darkroom/srgb.h>

#include <QSet>

#include <algorithm>
#include <cmath>
#include <limits>

namespace editor {
namespace {

using darkroom::Buffer;

int byte(float v) { return std::clamp(int(std::lround(v * 255.0f)), 0, 255); }
int srgbByte(float linear) { return byte(darkroom::linearToSrgb(std::clamp(linear, 0.0f, 1.0f))); }

std::vector<float> channelValues(const Buffer& b, const std::string& name) {
    std::vector<float> v(b.pixelCount());
    if (const float* f = b.hostFloat(name)) std::copy(f, f + v.size(), v.begin());
    else if (const std::uint32_t* u = b.hostUInt(name))
        for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(u[i]);
    return v;
}

// Range over finite values; for depth, infinite background is left out.
std::pair<float, float> finiteRange(const std::vector<float>& v) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    for (float x : v)
        if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    if (lo > hi) return {0.0f, 1.0f};
    if (lo == hi) hi = lo + 1.0f;
    return {lo, hi};
}

}  // namespace

QStringList displayModes(const Buffer& b) {
    QStringList modes;
    const auto names = b.channelNames();
    auto has = [&](const char* n) { return b.hasChannel(n); };
    if ((has("R") && has("G") && has("B")) || has("Y")) modes << QStringLiteral("Colour");
    if (has("Z")) modes << QStringLiteral("Depth Z");
    QSet<QString> groups;
    for (const auto& n : names) {
        const QString q = QString::fromStdString(n);
        if (q.endsWith(".x") && has((n.substr(0, n.size() - 2) + ".y").c_str()) &&
            has((n.substr(0, n.size() - 2) + ".z").c_str()) && !groups.contains(q.chopped(2))) {
            groups.insert(q.chopped(2));
            modes << QStringLiteral("Vector ") + q.chopped(2);
        }
    }
    for (const auto& n : names) modes << QStringLiteral("Channel ") + QString::fromStdString(n);
    return modes;
}

QImage renderDisplay(const Buffer& b, const QString& mode) {
    const int w = b.width(), h = b.height();
    QImage img(w, h, QImage::Format_ARGB32);
    img.fill(Qt::black);
    if (w <= 0 || h <= 0) return img;
    const std::size_t n = b.pixelCount();
    auto put = [&](std::size_t i, int r, int g, int bl, int a) {
        reinterpret_cast<QRgb*>(img.scanLine(int(i / w)))[i % w] = qRgba(r, g, bl, a);
    };
    if (mode == QLatin1String("Colour")) {
        const bool grey = !b.hasChannel("R");
        const auto r = channelValues(b, grey ? "Y" : "R");
        const auto g = grey ? r : channelValues(b, "G");
        const auto bb = grey ? r : channelValues(b, "B");
        const bool alpha = b.hasChannel("A");
        const auto a = alpha ? channelValues(b, "A") : std::vector<float>();
        for (std::size_t i = 0; i < n; ++i)
            put(i, srgbByte(r[i]), srgbByte(g[i]), srgbByte(bb[i]), alpha ? byte(a[i]) : 255);
    } else if (mode.startsWith(QLatin1String("Vector "))) {
        const std::string base = mode.mid(7).toStdString();
        const auto x = channelValues(b, base + ".x"), y = channelValues(b, base + ".y"),
                   z = channelValues(b, base + ".z");
        for (std::size_t i = 0; i < n; ++i)
            put(i, byte(0.5f + 0.5f * x[i]), byte(0.5f + 0.5f * y[i]), byte(0.5f + 0.5f * z[i]),
                std::isfinite(x[i]) ? 255 : 0);
    } else {
        const bool depth = mode == QLatin1String("Depth Z");
        const std::string name = depth ? "Z" : mode.mid(8).toStdString();
        const auto v = channelValues(b, name);
        const bool grey = depth || name == "AO" || name == "A";
        const auto [lo, hi] = (name == "AO" || name == "A") ? std::pair<float, float>(0, 1) : finiteRange(v);
        static const auto table = darkroom::loadColorMap("viridis").table(256);
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(v[i])) {
                put(i, 0, 0, 0, 0);  // background (infinite depth, NaN) shows the checkerboard
                continue;
            }
            float t = std::clamp((v[i] - lo) / (hi - lo), 0.0f, 1.0f);
            if (depth) t = 1.0f - t;  // near is bright
            if (grey) {
                const int c = byte(t);
                put(i, c, c, c, 255);
            } else {
                const auto& c = table[std::size_t(std::lround(t * 255.0f))];
                put(i, srgbByte(c.r), srgbByte(c.g), srgbByte(c.b), 255);
            }
        }
    }
    return img;
}

QString probeText(const Buffer& b, int x, int y) {
    if (x < 0 || y < 0 || x >= b.width() || y >= b.height()) return {};
    const std::size_t i = std::size_t(y) * std::size_t(b.width()) + std::size_t(x);
    QString s = QStringLiteral("x %1, y %2 |").arg(x).arg(y);
    for (const auto& c : b.channels()) {
        s += QLatin1Char(' ') + QString::fromStdString(c.name) + QLatin1Char(' ');
        if (const float* f = b.hostFloat(c.name)) s += QString::number(f[i], 'g', 6);
        else if (const std::uint32_t* u = b.hostUInt(c.name)) s += QString::number(u[i]);
    }
    return s;
}

}  // namespace editor
