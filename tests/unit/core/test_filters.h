#pragma once
// Small filters registered as built-ins for the graph/evaluator tests. Each
// counts its executions so caching can be checked from outside.
#include <darkroom/darkroom.h>
#include <darkroom/core/registry.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

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
        float* v = out->writeFloat("value");
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
        float* o = out->writeFloat("value");
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
        float* o = out->writeFloat("value");
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
        float* d = out->writeFloat("value");
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
        // Reads every channel, as a writer does.
        auto in = ctx.requireImage("image");
        for (const auto& c : in->channels()) (void)in->plane(c.name);
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

// Two planes "a" and "b", every pixel = the parameter of the same name.
class TwoPlanes final : public darkroom::Filter {
    darkroom::FloatIn a_{"a", 1.0, -1e9, 1e9, "Value of plane a"};
    darkroom::FloatIn b_{"b", 2.0, -1e9, 1e9, "Value of plane b"};
    darkroom::ImageOut out_{"image", "Planes a and b", {"a", "b"}};

public:
    darkroom::PortList ports() const override { return {a_, b_, out_}; }
    void execute(darkroom::Context& ctx) override {
        auto out = ctx.allocate(4, 3, {"a", "b"}, darkroom::Fill::None);
        std::fill_n(out->writeFloat("a"), out->pixelCount(), float(ctx.get(a_)));
        std::fill_n(out->writeFloat("b"), out->pixelCount(), float(ctx.get(b_)));
        ctx.set(out_, out);
    }
};

// Adds plane "c" = 2a, reading only "a"; everything else is passed on.
class DoubleA final : public darkroom::Filter {
    darkroom::ImageIn in_{"image", "Needs a", {"a"}};
    darkroom::ImageOut out_{"image", "Input plus c = 2a", {"c"}};

public:
    darkroom::PortList ports() const override { return {in_, out_}; }
    void execute(darkroom::Context& ctx) override {
        auto in = ctx.get(in_);
        auto out = ctx.derive(in, {"c"}, darkroom::Fill::None);
        const float* a = in->requireFloat("a");
        float* c = out->writeFloat("c");
        for (std::size_t i = 0; i < in->pixelCount(); ++i) c[i] = 2 * a[i];
        ctx.set(out_, out);
    }
};

// Reads a and b but writes plane "c" = a: when only b changes it re-runs and
// makes a bit-identical plane.
class CopyAReadingB final : public darkroom::Filter {
    darkroom::ImageIn in_{"image", "Needs a and b", {"a", "b"}};
    darkroom::ImageOut out_{"image", "c = a (b is read and ignored)", {"c"}};

public:
    darkroom::PortList ports() const override { return {in_, out_}; }
    void execute(darkroom::Context& ctx) override {
        auto in = ctx.get(in_);
        const float* a = in->requireFloat("a");
        (void)in->requireFloat("b");
        auto out = ctx.allocate(in->width(), in->height(), {"c"}, darkroom::Fill::None);
        std::copy_n(a, in->pixelCount(), out->writeFloat("c"));
        ctx.set(out_, out);
    }
};

// Adds plane "d" = c + 1, reading only "c".
class IncrementC final : public darkroom::Filter {
    darkroom::ImageIn in_{"image", "Needs c", {"c"}};
    darkroom::ImageOut out_{"image", "Input plus d = c + 1", {"d"}};

public:
    darkroom::PortList ports() const override { return {in_, out_}; }
    void execute(darkroom::Context& ctx) override {
        auto in = ctx.get(in_);
        auto out = ctx.derive(in, {"d"}, darkroom::Fill::None);
        const float* c = in->requireFloat("c");
        float* d = out->writeFloat("d");
        for (std::size_t i = 0; i < in->pixelCount(); ++i) d[i] = c[i] + 1;
        ctx.set(out_, out);
    }
};

// Publishes its input itself (a pass that changes nothing).
class Forward final : public darkroom::Filter {
    darkroom::ImageIn in_{"image", "Anything"};
    darkroom::ImageOut out_{"image", "The input, the same pointer"};

public:
    darkroom::PortList ports() const override { return {in_, out_}; }
    void execute(darkroom::Context& ctx) override { ctx.set(out_, ctx.get(in_)); }
};

// A 1x1 image whose value is the number written in a text file.
class FileNumber final : public darkroom::Filter {
    darkroom::PathIn path_{"path", "", "A text file holding one number"};
    darkroom::ImageOut out_{"image", "One pixel", {"value"}};

public:
    darkroom::PortList ports() const override { return {path_, out_}; }
    void execute(darkroom::Context& ctx) override {
        std::FILE* f = std::fopen(ctx.get(path_).c_str(), "r");
        if (!f) throw darkroom::Error("cannot open " + ctx.get(path_));
        double v = 0;
        if (std::fscanf(f, "%lf", &v) != 1) v = -1;
        std::fclose(f);
        auto out = ctx.allocate(1, 1, {"value"});
        out->writeFloat("value")[0] = float(v);
        ctx.set(out_, out);
    }
};

// Asks for an uninitialised plane and writes nothing: what poisoning catches.
class ForgetsToWrite final : public darkroom::Filter {
    darkroom::ImageOut out_{"image", "Never written", {"value"}};

public:
    darkroom::PortList ports() const override { return {out_}; }
    void execute(darkroom::Context& ctx) override { ctx.set(out_, ctx.allocate(2, 2, {"value"}, darkroom::Fill::None)); }
};

// Throws an error that names nothing: the host adds the node, once.
class Complains final : public darkroom::Filter {
    darkroom::ImageOut out_{"image", "Never produced"};

public:
    darkroom::PortList ports() const override { return {out_}; }
    void execute(darkroom::Context&) override { throw darkroom::Error("the input is not what was expected"); }
};

// A sink that logs its sequence bracket and executions ("begin", "execute
// 3", "end completed", "end early") to bracketLog(), and whose endSequence
// throws when `failEnd` was set.
inline std::vector<std::string>& bracketLog() {
    static std::vector<std::string> log;
    return log;
}
class Bracketed final : public darkroom::Filter {
    darkroom::ImageIn image_{"image", "Consumed"};
    darkroom::IntIn tag_{"tag", 0, 0, 1000, "Logged with each execution"};
    darkroom::BoolIn failEnd_{"failEnd", false, "endSequence throws"};
    bool failEnd = false;

public:
    darkroom::PortList ports() const override { return {image_, tag_, failEnd_}; }
    void beginSequence(const darkroom::SequenceInfo& info) override {
        bracketLog().push_back("begin " + std::to_string(info.length));
    }
    void execute(darkroom::Context& ctx) override {
        (void)ctx.get(image_);
        failEnd = ctx.get(failEnd_);
        bracketLog().push_back("execute " + std::to_string(ctx.get(tag_)));
    }
    void endSequence(const darkroom::SequenceInfo&, bool completed) override {
        bracketLog().push_back(completed ? "end completed" : "end early");
        if (failEnd) throw darkroom::Error("could not let go");
    }
};

inline void registerAll(darkroom::Registrar& r) {
    r.addFilter<Bracketed>("TestBracketed", "Test", "Logs its sequence bracket.");
    r.addFilter<TwoPlanes>("TestTwoPlanes", "Test", "Planes a and b.");
    r.addFilter<DoubleA>("TestDoubleA", "Test", "c = 2a, passing the rest on.");
    r.addFilter<CopyAReadingB>("TestCopyAReadingB", "Test", "c = a, reading b too.");
    r.addFilter<IncrementC>("TestIncrementC", "Test", "d = c + 1, passing the rest on.");
    r.addFilter<Forward>("TestForward", "Test", "Publishes its input.");
    r.addFilter<FileNumber>("TestFileNumber", "Test", "A number from a file.");
    r.addFilter<ForgetsToWrite>("TestForgetsToWrite", "Test", "Leaves its output unwritten.");
    r.addFilter<Complains>("TestComplains", "Test", "Fails with a plain message.");
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
