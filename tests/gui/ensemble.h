#pragma once
// A multi-parameter Cinema database as a simulation campaign writes it, for
// the explorer's GUI tests and the editor benchmark (bench/editor): a
// data.csv with the numeric columns time, phi, frequency and amplitude and
// the text column model, written directly (as another tool would), and one
// small OpenEXR product per row: a scalar field `value` made from the
// row's parameters, and a channel `row` holding the row's index, so a test
// can tell which row the render view shows.
#include <cstddef>
#include <string>

namespace guitest {

struct EnsembleRow {
    double time = 0, phi = 0, amplitude = 0;
    int frequency = 1;
    std::string model;
};

// Row i's parameters: every combination of 20 times, 8 angles, 3 models and
// 5 frequencies in the first 2,400 rows, each row its own amplitude.
EnsembleRow ensembleRow(std::size_t i);

// Writes `rows` rows with products of size x size pixels into `folder`
// (a .cdb path, created).
void writeEnsemble(const std::string& folder, std::size_t rows, int size);

// The same, kept between runs: `folder` is written (beside it, then renamed
// into place) unless a complete ensemble of that size is there already.
// Every product is written with fsync, so 2,400 of them take seconds, and
// each GUI test function runs in its own process.
void ensureEnsemble(const std::string& folder, std::size_t rows, int size);

}  // namespace guitest
