#include "ensemble.h"

#include <darkroom/data/image_io.h>

#include "test_support.h"

#include <charconv>
#include <cstdint>
#include <cmath>
#include <filesystem>
#include <numbers>

namespace guitest {
namespace {

std::string number(double v) {
    char buf[32];
    return std::string(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

float field(const EnsembleRow& r, double u, double v) {
    // A wave across the frame at angle phi, under an envelope per model.
    const double a = r.phi * std::numbers::pi / 180.0;
    const double along = u * std::cos(a) + v * std::sin(a);
    const double rr = u * u + v * v;
    double envelope = std::exp(-2.5 * rr);
    if (r.model == "navier-stokes") envelope = 1.0 / (1.0 + 6.0 * rr);
    if (r.model == "lattice-boltzmann") envelope = 0.6 + 0.4 * std::cos(5.0 * std::atan2(v, u) + r.time);
    return float(r.amplitude * std::sin(r.frequency * 3.0 * along - r.time) * envelope);
}

}  // namespace

EnsembleRow ensembleRow(std::size_t i) {
    static const char* const kModels[] = {"euler", "navier-stokes", "lattice-boltzmann"};
    EnsembleRow r;
    r.time = double(i % 20) * 0.5;
    r.phi = double((i / 20) % 8) * 45.0;
    r.model = kModels[(i / 160) % 3];
    r.frequency = 1 + int((i / 480) % 5);
    // A well-mixed hash of i: amplitudes spread over [0.1, 1) in steps of 0.001.
    std::uint64_t h = i * 0x9E3779B97F4A7C15ULL;
    h ^= h >> 29;
    h *= 0xBF58476D1CE4E5B9ULL;
    h ^= h >> 32;
    r.amplitude = 0.1 + double(h % 900) / 1000.0;
    return r;
}

void writeEnsemble(const std::string& folder, std::size_t rows, int size) {
    std::filesystem::create_directories(folder + "/p");
    std::string csv = "time,phi,model,frequency,amplitude,FILE\n";
    for (std::size_t i = 0; i < rows; ++i) {
        const EnsembleRow r = ensembleRow(i);
        const std::string file = "p/" + std::to_string(i) + ".exr";
        auto img = darkroom::test::makeImage(size, size, {"value", "row"}, [&](int x, int y, int c) {
            if (c == 1) return float(i);
            return field(r, (x + 0.5) / size * 2.0 - 1.0, (y + 0.5) / size * 2.0 - 1.0);
        });
        darkroom::writeImage(*img, folder + "/" + file);
        csv += number(r.time) + "," + number(r.phi) + "," + r.model + "," + std::to_string(r.frequency) + "," +
               number(r.amplitude) + "," + file + "\n";
    }
    darkroom::test::writeText(folder + "/data.csv", csv);
}

void ensureEnsemble(const std::string& folder, std::size_t rows, int size) {
    namespace fs = std::filesystem;
    const std::string stamp = std::to_string(rows) + " rows of " + std::to_string(size) + " px, version 1\n";
    if (darkroom::test::readText(folder + "/.ensemble") == stamp) return;
    const std::string partial = folder + ".partial";
    fs::remove_all(partial);
    writeEnsemble(partial, rows, size);
    darkroom::test::writeText(partial + "/.ensemble", stamp);
    fs::remove_all(folder);
    fs::rename(partial, folder);
}

}  // namespace guitest
