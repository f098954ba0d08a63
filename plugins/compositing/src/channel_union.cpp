#include "channel_union.h"

#include <darkroom/error.h>
#include <darkroom/layers.h>

namespace darkroom {

std::vector<ChannelDesc> channelUnion(const std::vector<BufferPtr>& inputs) {
    std::vector<ChannelDesc> out;
    std::vector<std::size_t> firstInput;  // which input introduced out[k], for the error message
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const int layerCount = layers::count(*inputs[i]);
        for (const ChannelDesc& c : inputs[i]->channels()) {
            // The composite is one layer: the deeper layers of a layered
            // input are blended into its colour, not carried.
            const int layer = layerCount > 1 ? layers::parse(c.name).first : 0;
            if (layer > 0 && layer < layerCount) continue;
            bool found = false;
            for (std::size_t k = 0; k < out.size() && !found; ++k) {
                if (out[k].name != c.name) continue;
                found = true;
                if (out[k].type != c.type)
                    throw Error("channel '" + c.name + "' is " + toString(out[k].type) + " in input " +
                                std::to_string(firstInput[k]) + " but " + toString(c.type) + " in input " +
                                std::to_string(i) + "; every input must give a channel the same type");
            }
            if (!found) {
                out.push_back(c);
                firstInput.push_back(i);
            }
        }
    }
    return out;
}

}  // namespace darkroom
