// Moves meshes that are placed only once into world space, so most scenes need one BVH level.
#pragma once

#include "scene/scene.h"

namespace wp {

// Returns `scene` with every mesh that exactly one instance places (with an invertible
// transform) transformed into world space and merged into one mesh under an identity
// instance, as Cycles does: a ray then walks one BVH over that geometry instead of a
// top-level BVH whose leaves each start another traversal. Meshes placed several times stay
// instanced, and so do animated and moving instances and deforming meshes. Front faces keep
// glTF's rule (a transform with a negative determinant turns clockwise triangles into front
// faces), so mirrored meshes get their winding swapped (and their TANGENT bitangent signs
// flipped).
Scene bakeSingleUseMeshes(const Scene& scene);

}  // namespace wp
