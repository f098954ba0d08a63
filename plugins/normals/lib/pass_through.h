#pragma once
// Helpers every depth-based pass of this folder family (Normals, IBS, SSDD)
// shares: the output carries all input channels unchanged and adds its own,
// and the camera must travel with the depth.
#include <darkroom/buffer.h>
#include <darkroom/context.h>

#include <memory>
#include <string>
#include <vector>

namespace darkroom::passes {

// Allocates an output of the input's size holding every input channel (same
// type, copied in parallel) plus `added` float channels; an added channel the
// input already has is not copied (the pass overwrites it). Metadata is copied.
std::shared_ptr<WritableBuffer> allocatePassThrough(Context& ctx, const Buffer& in,
                                                    const std::vector<std::string>& added);

// The camera in the metadata, with its resolution set to the buffer's (a
// resized image keeps its view). Throws darkroom::Error naming `what`
// (e.g. "Normals 'n': input 'image'") when there is none.
Camera requireCamera(const Buffer& in, const std::string& what);

// True where a depth is usable surface: finite (+inf is background, NaN and
// -inf are treated as no data too).
inline bool isSurface(float z) { return z - z == 0.0f; }

}  // namespace darkroom::passes
