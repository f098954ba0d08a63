#pragma once
// The output channel list of a composite: every channel of every input, by
// name, in order of first appearance; of a layered input (layers.h) only
// its front layer's channels (the composite is one layer).
#include <darkroom/buffer.h>

#include <string>
#include <vector>

namespace darkroom {

// Throws darkroom::Error when one name has different types in different
// inputs, naming the channel, both inputs and both types.
std::vector<ChannelDesc> channelUnion(const std::vector<BufferPtr>& inputs);

}  // namespace darkroom
