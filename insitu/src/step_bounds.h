#pragma once
// The bounds a capture checks its cameras against (session_setup.h): the
// step's objects, radii of lines and points included, on every rank.
#include "ranks.h"

#include <darkroom/scene.h>

#include <vector>

namespace darkroom::embree {
struct ObjectView;
}  // namespace darkroom::embree

namespace darkroom::insitu {

// Vertices with a coordinate that is not finite are left out (Embree leaves
// their primitives out too); so is a radius that is not.
Bounds boundsOf(const std::vector<embree::ObjectView>& objects);

// The union of every rank's bounds, the same on every rank (collective).
Bounds agreeBounds(ProcessGroup& ranks, const Bounds& mine);

}  // namespace darkroom::insitu
