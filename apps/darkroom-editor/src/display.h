#pragma once
// Turning a Buffer into something to look at, independent of the widget:
// the display modes a buffer offers, what each mode maps (DisplaySpec, used
// alike by the render view's shader and by the CPU path below), the 8-bit
// image of one mode (thumbnails, "export view"), and the pixel probe's text.
#include <darkroom/buffer.h>

#include <QImage>
#include <QStringList>

#include <array>
#include <string>
#include <vector>

namespace editor {

// "Colour" (R, G, B[, A] or Y), "Depth Z", a vector group ("N" from N.x,
// N.y, N.z) shown as 0.5 + 0.5 v, and every other channel as a scalar in
// false colour ("AO" and "A" in grey).
QStringList displayModes(const darkroom::Buffer& b);
// The mode to show first: colour, else the first scalar that is not depth
// or occlusion (a G-buffer's data), else the first mode.
QString preferredMode(const QStringList& modes);

struct DisplaySpec {
    enum class Kind { Colour, Vector, Scalar, None };
    Kind kind = Kind::None;
    // Colour: R, G, B (Y three times for grey images); Vector: x, y, z;
    // Scalar: the channel. `alpha` names an alpha channel or is empty.
    std::vector<std::string> channels;
    std::string alpha;
    // Scalar: t = (v - low) / (high - low) clamped; `invert` makes near depth
    // bright; grey, or the viridis table; non-finite values are transparent.
    float low = 0, high = 1;
    bool invert = false;
    bool grey = false;
    bool operator==(const DisplaySpec&) const = default;
};
// For scalars this reads the channel once for its finite range.
DisplaySpec displaySpec(const darkroom::Buffer& b, const QString& mode);

// The viridis table of false colour, sRGB-encoded RGBA bytes (256 entries).
const std::array<std::array<unsigned char, 4>, 256>& falseColourTable();

// ARGB32 (straight alpha); colour is sRGB-encoded for the screen.
QImage renderDisplay(const darkroom::Buffer& b, const QString& mode);
// "x 12, y 4 | R 0.5 G 0.25 B 1 Z 3.2" for every channel of the pixel.
QString probeText(const darkroom::Buffer& b, int x, int y);

}  // namespace editor
