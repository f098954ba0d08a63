#include <darkroom/workflows/pipeline_inputs.h>

#include "entry_ports.h"

#include <darkroom/colormap.h>
#include <darkroom/error.h>
#include <darkroom/strings.h>
#include <darkroom/core/path_overlap.h>
#include <darkroom/data/cinema/database.h>

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <variant>

namespace darkroom::workflows {

namespace fs = std::filesystem;

namespace {

class InputCheck {
public:
    InputCheck(const Graph& g, const std::string& pipelinePath)
        : g_(g), pipeline_(pipelinePath), base_(fs::path(pipelinePath).parent_path().string()) {
        // What the pipeline writes, resolved as the evaluator resolves an
        // output without --output: an input naming it exists once the run
        // has written it (Movie reading the database a CinemaWriter fills).
        for (const Node& n : g.nodes())
            for (const PortSpec& in : g.ports(n).inputs)
                if (in.type == PortType::OutputPath && g.edgesInto(n.name, in.name).empty())
                    if (const std::string v = textOf(n, in); !v.empty()) written_.push_back(resolved(v));
    }

    Diagnostics run() {
        for (const Node& n : g_.nodes()) {
            const PortSpec* database = entryReaderDatabase(g_, n);
            for (const PortSpec& in : g_.ports(n).inputs) {
                if ((in.type != PortType::ColorMap && in.type != PortType::Path) ||
                    !g_.edgesInto(n.name, in.name).empty())
                    continue;
                const std::string value = textOf(n, in);
                if (value.empty()) continue;
                if (in.type == PortType::ColorMap) checkColorMap(n, in, value);
                if (in.type != PortType::Path || writtenByThePipeline(value)) continue;
                if (&in == database) checkDatabase(n, in, value);
                else checkExists(n, in, value);
            }
        }
        return std::move(out_);
    }

private:
    // A node's parameter or its port's default.
    static const Value& valueOf(const Node& n, const PortSpec& in) {
        const Value* v = n.parameter(in.name);
        return v ? *v : in.defaultValue;
    }
    // The text of a path or colour-map input; "" when it has none.
    static std::string textOf(const Node& n, const PortSpec& in) {
        const std::string* s = std::get_if<std::string>(&valueOf(n, in).storage());
        return s ? *s : std::string();
    }

    // As HostContext::resolveInputPath, with the pipeline's folder as base.
    std::string resolved(const std::string& path) const {
        const fs::path p(path);
        return p.is_absolute() || base_.empty() ? p.string() : (fs::path(base_) / p).lexically_normal().string();
    }
    // Where it was looked for, in a message: absolute, so that it does not
    // depend on the folder validate ran in.
    std::string shown(const std::string& path) const { return absoluteNormal(resolved(path)); }

    bool writtenByThePipeline(const std::string& value) const {
        const std::string path = resolved(value);
        for (const auto& w : written_)
            if (pathsOverlap(w, path)) return true;
        return false;
    }

    void report(const Node& n, const std::string& message, Diagnostic::Severity severity = Diagnostic::Severity::Error) {
        Diagnostic d;
        d.severity = severity;
        d.where = n.line ? fmt::format("{}:{}:{}", pipeline_, n.line, n.column) : pipeline_;
        d.message = fmt::format("node '{}' ({}): {}", n.name, n.type, message);
        d.node = n.name;
        out_.push_back(std::move(d));
    }

    void checkColorMap(const Node& n, const PortSpec& in, const std::string& value) {
        std::error_code ec;
        if (isColorMapPreset(value) || fs::is_regular_file(resolved(value), ec)) return;
        // Presets match ignoring case (isColorMapPreset); so does the suggestion.
        std::string lower = value;
        for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
        report(n, fmt::format("{} '{}' is neither a preset{} nor a file ({} does not exist); expected one of {} or "
                              "a ParaView colour-map JSON file",
                              in.name, value, didYouMean(lower, colorMapPresets()), shown(value),
                              join(colorMapPresets(), ", ")));
    }

    void checkExists(const Node& n, const PortSpec& in, const std::string& value) {
        std::error_code ec;
        if (fs::exists(resolved(value), ec)) return;
        report(n, fmt::format("{} '{}': {} does not exist; expected a file or folder to read", in.name, value,
                              shown(value)));
    }

    // Opened as the node opens it: data.csv is read (its rows parsed), its
    // products are not.
    void checkDatabase(const Node& n, const PortSpec& in, const std::string& value) {
        CsvReadOptions o;
        const PortSpec* strict = g_.ports(n).input("strict");
        const bool* on = strict ? std::get_if<bool>(&valueOf(n, *strict).storage()) : nullptr;
        o.strict = on && *on;
        try {
            const CinemaDatabase db = CinemaDatabase::open(resolved(value), o);
            for (const auto& w : db.warnings()) report(n, w.where + ": " + w.message, w.severity);
        } catch (const Error& e) {
            report(n, fmt::format("{}: {}", in.name, e.what()));
        }
    }

    const Graph& g_;
    std::string pipeline_, base_;
    std::vector<std::string> written_;
    Diagnostics out_;
};

}  // namespace

Diagnostics checkPipelineInputs(const Graph& g, const std::string& pipelinePath) {
    return InputCheck(g, pipelinePath).run();
}

}  // namespace darkroom::workflows
