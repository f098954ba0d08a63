#pragma once
// The ao sweep's point-list method: PointListAO fed the stress scene's own
// particles or streamlines as the CSV a capture would store beside the entry
// (pointListCsv), timed with the reading of that file.
#include "harness.h"

#include <darkroom/accuracy/stress_scenes.h>

#include <vector>

namespace darkroom::accuracy::ao {

// True when the scene has points or lines objects to list.
bool hasPointList(const stress::StressScene& scene);

// Runs PointListAO on `gbuffer` with the scene's point and line objects as
// its list and a hard world radius `radius`; fills `ao` (one value per
// pixel) and returns the time in ms per megapixel (best of the harness's
// repeats).
double pointListAo(const Harness& harness, const stress::StressScene& scene, const BufferPtr& gbuffer, double radius,
                   std::vector<float>& ao);

}  // namespace darkroom::accuracy::ao
