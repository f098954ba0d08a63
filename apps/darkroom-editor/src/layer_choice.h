#pragma once
// What the render view shows of a layered buffer (issue 30; naming in
// sdk/include/darkroom/layers.h): one layer under the plain channel names,
// so the display modes, the probe and the export read it as any buffer, or
// the composite of a layered colour image, blended front to back with the
// same formula ColorMapping and Compositing use (darkroom/layer_blend.h).
#include <darkroom/buffer.h>

#include <QString>
#include <QStringList>

namespace editor {

// The chooser's entries for `b`: empty for an ordinary buffer (one layer),
// else ["composite"] when every layer has colour, then "front", "layer 1",
// ..., "layer K-1".
QStringList layerChoices(const darkroom::Buffer& b);
// The entry to show first: the composite when offered (the picture the
// layers make), else the front layer.
QString preferredLayerChoice(const QStringList& choices);

// Layer `layer` of `b` under the plain names: its planes are shared, not
// copied; channels of other layers are left out; metadata is kept.
darkroom::BufferPtr layerView(const darkroom::Buffer& b, int layer);
// The front layer's channels with R, G, B, A and Z replaced by the front-to-
// back blend of the `layers` colour layers of `b` (straight alpha; a layer
// without A is opaque; Z is the nearest surface that shows, +inf where none
// does, where R, G, B, A are 0).
darkroom::BufferPtr compositeView(const darkroom::Buffer& b, int layers);
// The buffer to show for `choice` (an entry of layerChoices(*b)); `b` itself
// for an empty or unknown choice.
darkroom::BufferPtr chooseLayer(const darkroom::BufferPtr& b, const QString& choice);

}  // namespace editor
