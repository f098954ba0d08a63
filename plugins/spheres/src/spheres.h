#pragma once
#include <darkroom/filter.h>

namespace darkroom {

// Draws a list of points as exactly ray-cast spheres into a G-buffer with the
// camera and size of another image, to composite with it.
class Spheres final : public Filter {
public:
    PortList ports() const override { return {image_, points_, row_, radius_, radiusScale_, result_}; }
    void execute(Context& ctx) override;

private:
    ImageIn image_{"image",
                   "The image the spheres are drawn for: only its camera and size are used (connect the G-buffer "
                   "they are composited with)"};
    PathIn points_{"points", "",
                   "The point list: a CSV with columns x, y, z and optionally radius and fields, or the vertices of "
                   "a .ply/.obj/.off/.stl/.vtk/.vtp/.vtu file. {column} placeholders are filled from `row`, e.g. "
                   "{FILE_maxima} for the list a capture stored beside each entry"};
    RowIn row_{"row", "The Cinema row for placeholders in `points` (connect CinemaReader's row)"};
    FloatIn radius_{"radius", 0.02, 0.0, 1e9, "Radius in world units for points the file gives none"};
    FloatIn radiusScale_{"radiusScale", 1.0, 0.0, 1e9, "Multiplies every radius (the file's or `radius`)"};
    ImageOut result_{"image",
                     "A G-buffer of the input's size and camera: Z (planar depth, +inf where no sphere), world-space "
                     "normals N.x, N.y, N.z, one channel per field of the list, and pointId (uint32, the point's "
                     "row; 0xffffffff where none); NaN where no sphere",
                     {"Z", "N.x", "N.y", "N.z"}};
};

}  // namespace darkroom
