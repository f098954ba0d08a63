// Example pass: inverts the colour of an image (1 - c), leaving alpha alone,
// blended with the original by `amount`. The whole plugin is this file.
#include <darkroom/darkroom.h>

namespace {

class Invert final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.imageIn("image", "Linear RGBA colour", {"R", "G", "B"});
        p.floatIn("amount", 1.0, 0.0, 1.0, "0 keeps the input, 1 inverts fully");
        p.imageOut("image", "Inverted colour; other channels pass through");
        return p;
    }

    void execute(darkroom::Context& ctx) override {
        const darkroom::BufferPtr in = ctx.requireImage("image");
        auto out = ctx.allocate(in->width(), in->height(), in->channels());
        out->metadata() = in->metadata();
        const float amount = float(ctx.getFloat("amount"));
        const std::size_t n = in->pixelCount();
        for (const auto& c : in->channels()) {
            const bool colour = c.name == "R" || c.name == "G" || c.name == "B";
            if (c.type == darkroom::ChannelType::UInt32) {
                std::copy_n(in->hostUInt(c.name), n, out->hostUInt(c.name));
                continue;
            }
            const float* s = in->hostFloat(c.name);
            float* d = out->hostFloat(c.name);
            ctx.parallelFor(0, in->height(), 16, [&](int y0, int y1) {
                for (std::size_t i = std::size_t(y0) * in->width(); i < std::size_t(y1) * in->width(); ++i)
                    d[i] = colour ? s[i] + amount * (1.0f - 2.0f * s[i]) : s[i];
            });
        }
        ctx.setOutput("image", darkroom::BufferPtr(out));
    }
};

void registerTypes(darkroom::Registrar& r) {
    r.addFilter<Invert>("Invert", "Color", "Inverts linear RGB colour (SDK example plugin).");
}

}  // namespace

DARKROOM_PLUGIN("invert-example", "1.0.0", registerTypes)
