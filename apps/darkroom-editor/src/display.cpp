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
int srgbByte(float linear) {
    if (!(linear > 0.0f)) return 0;  // also NaN
    return byte(darkroom::linearToSrgb(std::min(linear, 1.0f)));
}

std::vector<float> channelValues(const Buffer& b, const std::string& name) {
    std::vector<float> v(b.pixelCount());
    if (const float* f = b.hostFloat(name)) std::copy(f, f + v.size(), v.begin());
    else if (const std::uint32_t* u = b.hostUInt(name))
        for (std::size_t i = 0; i < v.size(); ++i) v[i] = float(u[i]);
    return v;
}

// Range over finite values; for depth, infinite background is left out.
std::pair<float, float> finiteRange(const Buffer& b, const std::string& name) {
    float lo = std::numeric_limits<float>::max(), hi = std::numeric_limits<float>::lowest();
    const std::size_t n = b.pixelCount();
    if (const float* f = b.hostFloat(name)) {
        for (std::size_t i = 0; i < n; ++i)
            if (std::isfinite(f[i])) lo = std::min(lo, f[i]), hi = std::max(hi, f[i]);
    } else if (const std::uint32_t* u = b.hostUInt(name)) {
        for (std::size_t i = 0; i < n; ++i) lo = std::min(lo, float(u[i])), hi = std::max(hi, float(u[i]));
    }
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

QString preferredMode(const QStringList& modes) {
    if (modes.isEmpty()) return {};
    if (modes.contains(QStringLiteral("Colour"))) return QStringLiteral("Colour");
    for (const QString& m : modes)
        if (m.startsWith(QLatin1String("Channel ")) && m != QLatin1String("Channel Z") &&
            m != QLatin1String("Channel AO") && m != QLatin1String("Channel A"))
            return m;
    return modes.front();
}

DisplaySpec displaySpec(const Buffer& b, const QString& mode) {
    DisplaySpec s;
    if (mode == QLatin1String("Colour")) {
        s.kind = DisplaySpec::Kind::Colour;
        if (b.hasChannel("R")) s.channels = {"R", "G", "B"};
        else s.channels = {"Y", "Y", "Y"};
        if (b.hasChannel("A")) s.alpha = "A";
    } else if (mode.startsWith(QLatin1String("Vector "))) {
        s.kind = DisplaySpec::Kind::Vector;
        const std::string base = mode.mid(7).toStdString();
        s.channels = {base + ".x", base + ".y", base + ".z"};
    } else if (mode == QLatin1String("Depth Z") || mode.startsWith(QLatin1String("Channel "))) {
        s.kind = DisplaySpec::Kind::Scalar;
        const bool depth = mode == QLatin1String("Depth Z");
        const std::string name = depth ? "Z" : mode.mid(8).toStdString();
        s.channels = {name};
        s.invert = depth;
        s.grey = depth || name == "AO" || name == "A";
        if (name == "AO" || name == "A") s.low = 0, s.high = 1;
        else std::tie(s.low, s.high) = finiteRange(b, name);
    }
    for (const auto& c : s.channels)
        if (!b.hasChannel(c)) return {};
    return s;
}

const std::array<std::array<unsigned char, 4>, 256>& falseColourTable() {
    static const auto table = [] {
        std::array<std::array<unsigned char, 4>, 256> t{};
        const auto colours = darkroom::loadColorMap("viridis").table(256);
        for (std::size_t i = 0; i < 256; ++i)
            t[i] = {static_cast<unsigned char>(srgbByte(colours[i].r)), static_cast<unsigned char>(srgbByte(colours[i].g)),
                    static_cast<unsigned char>(srgbByte(colours[i].b)), 255};
        return t;
    }();
    return table;
}

QImage renderDisplay(const Buffer& b, const QString& mode) {
    const int w = b.width(), h = b.height();
    QImage img(std::max(w, 1), std::max(h, 1), QImage::Format_ARGB32);
    img.fill(Qt::black);
    const DisplaySpec s = displaySpec(b, mode);
    if (w <= 0 || h <= 0 || s.kind == DisplaySpec::Kind::None) return img;
    const std::size_t n = b.pixelCount();
    auto put = [&](std::size_t i, int r, int g, int bl, int a) {
        reinterpret_cast<QRgb*>(img.scanLine(int(i / w)))[i % w] = qRgba(r, g, bl, a);
    };
    if (s.kind == DisplaySpec::Kind::Colour) {
        const auto r = channelValues(b, s.channels[0]), g = channelValues(b, s.channels[1]),
                   bb = channelValues(b, s.channels[2]);
        const auto a = s.alpha.empty() ? std::vector<float>() : channelValues(b, s.alpha);
        for (std::size_t i = 0; i < n; ++i)
            put(i, srgbByte(r[i]), srgbByte(g[i]), srgbByte(bb[i]), a.empty() ? 255 : byte(a[i]));
    } else if (s.kind == DisplaySpec::Kind::Vector) {
        const auto x = channelValues(b, s.channels[0]), y = channelValues(b, s.channels[1]),
                   z = channelValues(b, s.channels[2]);
        for (std::size_t i = 0; i < n; ++i)
            put(i, byte(0.5f + 0.5f * x[i]), byte(0.5f + 0.5f * y[i]), byte(0.5f + 0.5f * z[i]),
                std::isfinite(x[i]) ? 255 : 0);
    } else {
        const auto v = channelValues(b, s.channels[0]);
        const auto& table = falseColourTable();
        for (std::size_t i = 0; i < n; ++i) {
            if (!std::isfinite(v[i])) {
                put(i, 0, 0, 0, 0);  // background (infinite depth, NaN) shows the checkerboard
                continue;
            }
            float t = std::clamp((v[i] - s.low) / (s.high - s.low), 0.0f, 1.0f);
            if (s.invert) t = 1.0f - t;  // near is bright
            if (s.grey) {
                const int c = byte(t);
                put(i, c, c, c, 255);
            } else {
                const auto& c = table[std::size_t(std::lround(t * 255.0f))];
                put(i, c[0], c[1], c[2], 255);
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
