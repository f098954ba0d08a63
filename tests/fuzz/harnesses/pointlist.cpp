// Point lists (.csv beside each captured entry, read by the Spheres node):
// the reader either refuses the file (darkroom::Error) or returns points
// whose parts agree in length and whose positions are finite.
#include "harness.h"

#include <darkroom/error.h>
#include <darkroom/data/formats/point_list.h>

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    try {
        const darkroom::PointList list = darkroom::readPointListCsv(fuzz::writeInput(data, size, "points.csv"));
        fuzz::expect(list.radii.empty() || list.radii.size() == list.size(), "one radius per point, or none");
        for (const auto& f : list.fields) fuzz::expect(f.values.size() == list.size(), "one field value per point");
        for (const auto& c : list.centers)
            fuzz::expect(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z),
                         "points without a finite position are skipped");
    } catch (const darkroom::Error&) {
    }
    return 0;
}
