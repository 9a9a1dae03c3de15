// The benchmarks' test mesh: a UV sphere with a bumpy, optionally moving, displacement.
#pragma once

#include <cstddef>

#include "scene/scene.h"

namespace wp::bench {

// A UV sphere of about `triangles` triangles (material 0) whose radius is displaced by a few
// octaves of sines, so the surface is bumpy at several scales, like a scanned model. `phase`
// (radians) moves the largest bumps across the surface, for animation; deterministic.
Mesh displacedSphere(size_t triangles, float phase = 0.0f);

}  // namespace wp::bench
