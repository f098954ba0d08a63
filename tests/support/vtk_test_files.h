#pragma once
// Writes small ASCII VTK XML PolyData files (.vtp) and parallel files
// (.pvtp) in tests, so that no mesh file needs to be stored.
#include <cstdint>
#include <string>
#include <vector>

namespace darkroom::test {

struct VtpPiece {
    std::vector<float> points;  // x, y, z per point
    // Cells of each kind as point lists.
    std::vector<std::vector<std::uint32_t>> verts, lines, polys;
    // Named arrays of one component: point data (one per point) and cell
    // data (one per cell, in VTK's order: verts, lines, polys).
    std::vector<std::pair<std::string, std::vector<float>>> pointData, cellData;
};

void writeVtp(const std::string& path, const VtpPiece& piece);

// Writes `name`.pvtp in `folder` and its pieces `name`_<k>.vtp beside it
// (Source paths relative, as ParaView writes them); returns the .pvtp path.
std::string writePvtp(const std::string& folder, const std::string& name, const std::vector<VtpPiece>& pieces);

// A height field z = f(x, y) on a grid of `nx` x `ny` points over [-1, 1]^2,
// cut into `pieces` bands of rows. Neighbouring bands share their boundary
// row of points, each with its own copy (as VTK's piece writers do). Point
// data "height" (= z), cell data "band" (the piece index). Every band after
// the first has one polyline along its first row; the last band also has a
// vertex cell at each corner.
std::vector<VtpPiece> heightFieldPieces(int nx, int ny, int pieces);

}  // namespace darkroom::test
