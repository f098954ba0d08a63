#pragma once
// The gradient of a volume's scalar point array at its points, from which
// isosurfaces get their shading normals (as ParaView's Contour computes
// them): interpolated to each surface vertex like any point array, it is
// the field's normal there, smoother than the facets of the contour.
#include <darkroom/scene/volume.h>

#include <cstdint>
#include <vector>

namespace darkroom::volume {

// x, y, z per volume point, world units, at the points `wanted` marks (an
// isosurface needs the few around it, not the whole volume); zero
// elsewhere. Image data: central differences on the grid (one-sided on its
// faces), through the grid's spacing and direction. Unstructured grids: at
// each point, the mean of the gradients of the 3D cells around it, each the
// least-squares linear fit to the cell's corners (exact for a field linear
// in the cell). Zero where nothing gives a gradient (a point of no 3D cell,
// NaN values, flat cells).
std::vector<float> pointGradient(const VolumeMesh& v, const std::vector<float>& scalar,
                                 const std::vector<std::uint8_t>& wanted);

}  // namespace darkroom::volume
