#pragma once
// Turning a Buffer into something to look at, independent of the widget:
// the display modes a buffer offers, the 8-bit image of one mode, and the
// text of the pixel probe.
#include <darkroom/buffer.h>

#include <QImage>
#include <QStringList>

namespace editor {

// "Colour" (R, G, B[, A] or Y), "Depth Z", a vector group ("N" from N.x,
// N.y, N.z) shown as 0.5 + 0.5 v, and every other channel as a scalar in
// false colour ("AO" and "A" in grey).
QStringList displayModes(const darkroom::Buffer& b);
// ARGB32 (straight alpha); colour is sRGB-encoded for the screen.
QImage renderDisplay(const darkroom::Buffer& b, const QString& mode);
// "x 12, y 4 | R 0.5 G 0.25 B 1 Z 3.2" for every channel of the pixel.
QString probeText(const darkroom::Buffer& b, int x, int y);

}  // namespace editor
