// Example pass: inverts the colour of an image (1 - c), leaving alpha alone,
// blended with the original by `amount`. The whole plugin is this file.
#include <darkroom/darkroom.h>

namespace {

class Invert final : public darkroom::Filter {
    darkroom::ImageIn image{"image", "Linear RGBA colour", {"R", "G", "B"}};
    darkroom::FloatIn amount{"amount", 1.0, 0.0, 1.0, "0 keeps the input, 1 inverts fully"};
    darkroom::ImageOut result{"image", "Inverted colour; other channels pass through"};

public:
    darkroom::PortList ports() const override { return {image, amount, result}; }

    void execute(darkroom::Context& ctx) override {
        const darkroom::BufferPtr in = ctx.get(image);
        const float a = float(ctx.get(amount));
        // New R, G, B; every other channel is shared with the input, not copied.
        auto out = ctx.derive(in, {"R", "G", "B"}, darkroom::Fill::None);
        for (const char* c : {"R", "G", "B"}) {
            const float* s = in->requireFloat(c);
            float* d = out->writeFloat(c);
            ctx.parallelFor(0, in->height(), 16, [&](int y0, int y1) {
                for (std::size_t i = std::size_t(y0) * in->width(); i < std::size_t(y1) * in->width(); ++i)
                    d[i] = s[i] + a * (1.0f - 2.0f * s[i]);
            });
        }
        ctx.set(result, out);
    }
};

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<Invert>("Invert", "Color", "Inverts linear RGB colour (SDK example plugin).");
}

}  // namespace

DARKROOM_PLUGIN("invert-example", "1.0.0", registerTypes)
