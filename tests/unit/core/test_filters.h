#pragma once
// Small filters registered as built-ins for the graph/evaluator tests. Each
// counts its executions so caching can be checked from outside.
#include <darkroom/darkroom.h>
#include <darkroom/framework/registry.h>

#include <atomic>
#include <cmath>

namespace testfilters {

inline std::atomic<int> g_sinkCalls{0};

// w x h image, every pixel = value (+ x * gradient).
class Source final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.intIn("width", 4, 1, 4096, "Width");
        p.intIn("height", 3, 1, 4096, "Height");
        p.floatIn("value", 1.0, -1e9, 1e9, "Fill value");
        p.imageOut("image", "Constant image", {"value"});
        return p;
    }
    void execute(darkroom::Context& ctx) override {
        const int w = int(ctx.getInt("width")), h = int(ctx.getInt("height"));
        auto out = ctx.allocate(w, h, {{"value", darkroom::ChannelType::Float32}});
        float* v = out->hostFloat("value");
        for (std::size_t i = 0; i < out->pixelCount(); ++i) v[i] = float(ctx.getFloat("value"));
        ctx.setOutput("image", darkroom::BufferPtr(out));
    }
};

class Add final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.imageIn("a", "First", {"value"});
        p.imageIn("b", "Second", {"value"});
        p.floatIn("offset", 0.0, -1e9, 1e9, "Added to the sum");
        p.imageOut("image", "a + b + offset", {"value"});
        return p;
    }
    void execute(darkroom::Context& ctx) override {
        auto a = ctx.requireImage("a"), b = ctx.requireImage("b");
        if (a->width() != b->width() || a->height() != b->height()) throw darkroom::Error("sizes differ");
        auto out = ctx.allocate(a->width(), a->height(), {{"value", darkroom::ChannelType::Float32}});
        const float* pa = a->requireFloat("value");
        const float* pb = b->requireFloat("value");
        float* o = out->hostFloat("value");
        const float off = float(ctx.getFloat("offset"));
        for (std::size_t i = 0; i < out->pixelCount(); ++i) o[i] = pa[i] + pb[i] + off;
        ctx.setOutput("image", darkroom::BufferPtr(out));
    }
};

// Sum of any number of inputs: exercises `multiple` ports.
class Sum final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.imagesIn("images", "Input k (from 0) is weighted by k + 1");
        p.imageOut("image", "Sum", {"value"});
        return p;
    }
    void execute(darkroom::Context& ctx) override {
        auto in = ctx.images("images");
        if (in.empty()) throw darkroom::Error("nothing to sum");
        auto out = ctx.allocate(in[0]->width(), in[0]->height(), {{"value", darkroom::ChannelType::Float32}});
        float* o = out->hostFloat("value");
        for (std::size_t k = 0; k < in.size(); ++k) {
            const float* p = in[k]->requireFloat("value");
            for (std::size_t i = 0; i < out->pixelCount(); ++i) o[i] += float(k + 1) * p[i];
        }
        ctx.setOutput("image", darkroom::BufferPtr(out));
    }
};

// Per-pixel hashed noise with a row-parallel loop: results must not depend on threads.
class Noise final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.imageIn("image", "Input", {"value"});
        p.intIn("seed", 7, 0, 1000000, "Hash seed");
        p.imageOut("image", "Input plus noise", {"value"});
        return p;
    }
    void execute(darkroom::Context& ctx) override {
        auto in = ctx.requireImage("image");
        auto out = ctx.allocate(in->width(), in->height(), {{"value", darkroom::ChannelType::Float32}});
        const float* s = in->requireFloat("value");
        float* d = out->hostFloat("value");
        const std::uint32_t seed = std::uint32_t(ctx.getInt("seed"));
        const int w = in->width();
        ctx.parallelFor(0, in->height(), 1, [&](int y0, int y1) {
            for (int y = y0; y < y1; ++y)
                for (int x = 0; x < w; ++x) {
                    std::uint32_t h = seed ^ (std::uint32_t(x) * 73856093u) ^ (std::uint32_t(y) * 19349663u);
                    h ^= h >> 13;
                    h *= 0x5bd1e995u;
                    h ^= h >> 15;
                    const std::size_t i = std::size_t(y) * w + x;
                    d[i] = s[i] + float(h & 0xffff) / 65535.0f;
                }
        });
        ctx.setOutput("image", darkroom::BufferPtr(out));
    }
};

// Emits a float value: exercises connected value ports.
class Number final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.floatIn("x", 3.0, -1e9, 1e9, "The number");
        p.valueOut("value", darkroom::PortType::Float, "x");
        return p;
    }
    void execute(darkroom::Context& ctx) override { ctx.setOutput("value", darkroom::Value(ctx.getFloat("x"))); }
};

class Sink final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.imageIn("image", "Consumed");
        return p;
    }
    void execute(darkroom::Context& ctx) override {
        (void)ctx.requireImage("image");
        ++g_sinkCalls;
    }
};

class Throw final : public darkroom::Filter {
public:
    darkroom::PortList ports() const override {
        darkroom::PortList p;
        p.optionalImageIn("image", "Ignored");
        p.imageOut("image", "Never produced");
        return p;
    }
    void execute(darkroom::Context&) override { throw std::runtime_error("deliberate failure"); }
};

inline void registerAll(darkroom::Registrar& r) {
    r.addFilter<Source>("TestSource", "Test", "Constant image.");
    r.addFilter<Add>("TestAdd", "Test", "Adds two images.");
    r.addFilter<Sum>("TestSum", "Test", "Adds any number of images.");
    r.addFilter<Noise>("TestNoise", "Test", "Adds hashed noise.");
    r.addFilter<Number>("TestNumber", "Test", "A number.");
    r.addFilter<Sink>("TestSink", "Test", "Consumes an image.");
    r.addFilter<Throw>("TestThrow", "Test", "Always fails.");
}

inline darkroom::Registry& registry() {
    static darkroom::Registry* r = [] {
        auto* x = new darkroom::Registry();
        x->registerBuiltin("test", &registerAll);
        return x;
    }();
    return *r;
}

}  // namespace testfilters
