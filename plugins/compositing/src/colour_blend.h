#pragma once
// Compositing's colour for translucent surfaces (issue 30): where the
// nearest surface of a pixel is not opaque, R, G, B, A become the front-to-
// back blend of every colour layer of every input at that pixel, sorted by
// depth, so the result does not depend on the order of the inputs.
#include <darkroom/buffer.h>

#include <cstddef>
#include <string>
#include <vector>

namespace darkroom::compositing {

class ColourLayers {
public:
    // The layers (layers.h naming) of the inputs that hold R, G, B, A and
    // depth `depthName` as float32.
    ColourLayers(const std::vector<BufferPtr>& inputs, const std::string& depthName);
    // Whether any input has colour: without, there is nothing to blend.
    bool any() const { return !layers_.empty(); }
    // Pixels [row, row + width) of one row; winner[x] is the nearest input
    // (-1: background). out = R, G, B, A of the output, already holding the
    // winner's colour: pixels whose winner is opaque (A >= 1) or has no
    // colour keep it, so opaque inputs come out exactly as a z-buffer merge.
    void blendRow(std::size_t row, int width, const int* winner, float* const out[4]) const;

private:
    struct Layer {
        int input;
        const float *z, *r, *g, *b, *a;
    };
    std::vector<Layer> layers_;  // by input, then layer: the tie-break order of equal depths
    std::vector<const float*> frontAlpha_;  // per input, its front layer's A (nullptr: no colour)
};

}  // namespace darkroom::compositing
