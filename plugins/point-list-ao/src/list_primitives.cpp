#include "list_primitives.h"

#include <darkroom/view_geometry.h>

#include <cmath>

namespace darkroom::listao {

Primitives listPrimitives(const PointList& list, const Camera& camera, double fallbackRadius, double scale) {
    const ViewGeometry view(camera, camera.width, camera.height);
    const std::vector<float>* line = nullptr;
    for (const ScalarField& f : list.fields)
        if (f.name == kLineColumn && f.values.size() == list.size()) line = &f.values;

    std::vector<V3f> at(list.size());
    std::vector<float> radius(list.size());
    for (std::size_t i = 0; i < list.size(); ++i) {
        at[i] = view.toView(list.centers[i] - camera.position);
        const double r = list.radii.empty() || std::isnan(list.radii[i]) ? fallbackRadius : double(list.radii[i]);
        radius[i] = float(r * scale);
    }
    auto onLine = [&](std::size_t i) { return line && std::isfinite((*line)[i]); };
    auto sameLine = [&](std::size_t i, std::size_t j) { return onLine(i) && onLine(j) && (*line)[i] == (*line)[j]; };

    Primitives p;
    for (std::size_t i = 0; i < list.size(); ++i) {
        if (!onLine(i)) {
            if (radius[i] > 0) {
                p.centres.push_back(at[i]);
                p.radii.push_back(radius[i]);
            }
            continue;
        }
        if (i + 1 < list.size() && sameLine(i, i + 1) && (radius[i] > 0 || radius[i + 1] > 0)) {
            p.segA.push_back(at[i]);
            p.segB.push_back(at[i + 1]);
            p.segRa.push_back(radius[i]);
            p.segRb.push_back(radius[i + 1]);
        }
    }
    return p;
}

}  // namespace darkroom::listao
