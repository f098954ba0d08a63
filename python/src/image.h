#pragma once
// An image as Python sees it: a darkroom::Buffer shared with the pipeline
// that made it (nothing is copied), its channels as read-only numpy views.
#include <darkroom/buffer.h>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>

namespace darkroom::python {

struct Image {
    BufferPtr buffer;
};

// A read-only (height, width) view of the channel's plane; the array keeps
// the plane alive. Throws KeyError naming the channels there are.
pybind11::array channelView(const BufferPtr& buffer, const std::string& channel);

// The picture a person looks at: R, G, B (and A) sRGB-encoded as 8 bits,
// or, without colour, the first channel as grey over its finite range.
pybind11::array_t<std::uint8_t> toRgba8(const Buffer& buffer);

}  // namespace darkroom::python
