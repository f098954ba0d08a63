#pragma once
// One builder per stress-scene family. A builder fills the scene, camera,
// colour field and range, AO radius, focal distance, description and (where
// known) analytic AO; stress_scenes.cpp checks the knob, names the scene and
// widens the field range to cover every value.
#include <darkroom/accuracy/stress_scenes.h>

namespace darkroom::stress::detail {

using Builder = void (*)(StressScene& s, double knob, const Options& options);

// families_planes.cpp
void buildPlane(StressScene& s, double knob, const Options& options);
void buildCorner(StressScene& s, double knob, const Options& options);
void buildTerrain(StressScene& s, double knob, const Options& options);
void buildGrazing(StressScene& s, double knob, const Options& options);
void buildStripes(StressScene& s, double knob, const Options& options);
// families_thin.cpp
void buildParticles(StressScene& s, double knob, const Options& options);
void buildStreamlines(StressScene& s, double knob, const Options& options);
void buildSlabs(StressScene& s, double knob, const Options& options);
void buildStaircase(StressScene& s, double knob, const Options& options);
// families_objects.cpp
void buildBorder(StressScene& s, double knob, const Options& options);
void buildGyroid(StressScene& s, double knob, const Options& options);
// families_layers.cpp
void buildShells(StressScene& s, double knob, const Options& options);
void buildSheets(StressScene& s, double knob, const Options& options);

}  // namespace darkroom::stress::detail
