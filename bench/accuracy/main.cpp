// bench_accuracy: runs the accuracy sweeps (issue 6) and writes one CSV per
// sweep. scripts/accuracy.sh runs every sweep and plots the result.
//
//   bench_accuracy [--sweep NAME]... [--family NAME]... [--size N] [--quick]
//                  [--out DIR] [--images DIR] [--threads N] [--repeats N] [--list]
#include "harness.h"

#include <darkroom/error.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

int usage(const std::string& why) {
    std::cerr << "bench_accuracy: " << why << "\n"
              << "usage: bench_accuracy [--sweep NAME]... [--family NAME]... [--size N] [--quick] [--out DIR]\n"
              << "                      [--images DIR] [--threads N] [--repeats N] [--list]\n";
    return 2;
}

bool parseInt(const std::string& s, int& out) {
    char* end = nullptr;
    const long v = std::strtol(s.c_str(), &end, 10);
    if (s.empty() || *end || v < 0 || v > 1 << 16) return false;
    out = int(v);
    return true;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace darkroom::accuracy;
    Options options;
    std::vector<std::string> selected;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        auto next = [&](std::string& v) {
            if (i + 1 >= argc) return false;
            v = argv[++i];
            return true;
        };
        std::string v;
        if (a == "--list") {
            for (const auto& s : sweeps()) std::cout << s.name << "\t" << s.description << "\n";
            return 0;
        } else if (a == "--quick") {
            options.quick = true;
        } else if (a == "--sweep") {
            if (!next(v)) return usage("--sweep needs a name");
            selected.push_back(v);
        } else if (a == "--family") {
            if (!next(v)) return usage("--family needs a stress family name");
            options.families.push_back(v);
        } else if (a == "--size") {
            if (!next(v) || !parseInt(v, options.size) || options.size < 16) return usage("--size needs an integer >= 16");
        } else if (a == "--threads") {
            if (!next(v) || !parseInt(v, options.threads)) return usage("--threads needs an integer >= 0");
        } else if (a == "--repeats") {
            if (!next(v) || !parseInt(v, options.repeats) || options.repeats < 1) return usage("--repeats needs an integer >= 1");
        } else if (a == "--out") {
            if (!next(options.outDir)) return usage("--out needs a folder");
        } else if (a == "--images") {
            if (!next(options.imageDir)) return usage("--images needs a folder");
        } else {
            return usage("unknown argument '" + a + "'");
        }
    }
    for (const auto& name : selected) {
        bool known = false;
        for (const auto& s : sweeps()) known = known || s.name == name;
        if (!known) return usage("unknown sweep '" + name + "' (--list shows them)");
    }
    try {
        std::filesystem::create_directories(options.outDir);
        Harness harness(options);
        for (const auto& s : sweeps()) {
            if (!selected.empty() && std::find(selected.begin(), selected.end(), s.name) == selected.end()) continue;
            const std::string path = (std::filesystem::path(options.outDir) / (s.name + ".csv")).string();
            std::cerr << "sweep " << s.name << " -> " << path << "\n";
            Csv csv(path);
            s.fn(harness, csv);
        }
    } catch (const darkroom::Error& e) {
        std::cerr << "bench_accuracy: " << e.what() << "\n";
        return 1;
    }
    return 0;
}
