#include "limit_options.h"

#include <darkroom/limits.h>

#include <CLI/CLI.hpp>

#include <cctype>
#include <cmath>
#include <stdexcept>

namespace darkroom::cli {

std::uint64_t parseSize(const std::string& text) {
    std::size_t used = 0;
    double v = 0;
    try {
        v = std::stod(text, &used);
    } catch (const std::exception&) {
        throw std::invalid_argument("'" + text + "' is not a size (e.g. 1048576, 512M or 4G)");
    }
    std::string unit = text.substr(used);
    for (char& c : unit) c = char(std::toupper(static_cast<unsigned char>(c)));
    double scale = 1;
    if (!unit.empty() && std::string("KMGT").find(unit[0]) != std::string::npos) {
        scale = std::pow(1024.0, double(std::string("KMGT").find(unit[0]) + 1));
        unit.erase(0, 1);
    }
    if (!(unit.empty() || unit == "B" || unit == "IB"))
        throw std::invalid_argument("'" + text + "' has an unknown unit (use K, M, G or T)");
    const double bytes = v * scale;
    if (!std::isfinite(bytes) || bytes < 0 || bytes >= 18446744073709551616.0)
        throw std::invalid_argument("'" + text + "' is not a size from 0 to 16 EiB");
    return std::uint64_t(bytes);
}

void addLimitOptions(CLI::App& app) {
    auto size = [&app](Limit which, const std::string& help) {
        app.add_option_function<std::string>(
               limitOption(which),
               [which](const std::string& text) {
                   try {
                       setLimit(which, parseSize(text));
                   } catch (const std::invalid_argument& e) {
                       throw CLI::ValidationError(limitOption(which), e.what());
                   }
               },
               help)
            ->type_name("SIZE");
    };
    size(Limit::ImagePixels, "Largest image (width x height, in pixels; 256M = 16384 x 16384, the default) a file may "
                             "declare or a node may allocate");
    size(Limit::InputBytes, "Largest input file read whole: pipeline, scene, mesh, CSV, JSON (default 8G)");
    size(Limit::DecodedBytes, "Largest array decoded or generated from an input: inflated zlib data, .npy/.npz "
                              "members, EXR channels, streamlines (default 8G)");
    size(Limit::NodeBytes, "Memory one node may allocate for new image planes in one evaluation, e.g. 4G or 512M "
                           "(default: no limit)");
    app.add_option_function<double>(
           limitOption(Limit::NodeMilliseconds),
           [](double seconds) {
               if (!(seconds >= 0) || !std::isfinite(seconds))
                   throw CLI::ValidationError(limitOption(Limit::NodeMilliseconds), "must be a number of seconds >= 0");
               // Rounded up, so a tiny positive limit is not 0 (no limit).
               setLimit(Limit::NodeMilliseconds, std::uint64_t(std::ceil(seconds * 1000.0)));
           },
           "Wall time one node may take in one evaluation, in seconds; past it the node stops at its next "
           "row block and the run fails naming it (default 0: no limit)")
        ->type_name("SECONDS");
}

}  // namespace darkroom::cli
