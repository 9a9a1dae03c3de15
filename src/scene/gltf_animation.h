// Reading and validating glTF animations, skins and morph target counts.
#pragma once

#include <cstddef>
#include <vector>

#include "scene/gltf_context.h"
#include "scene/scene_animation.h"

namespace wp::gltf {

// The number of morph targets of glTF mesh `index`. Throws, naming the mesh, when its
// triangle primitives disagree on it or its default weights have another count.
size_t morphTargetCount(const Context& ctx, size_t index);

// Reads every animation. `morphTargets` gives, per glTF node, the morph target count of its
// mesh (0 without). Throws one line naming the animation, channel or sampler and what to do
// when a channel's node or sampler does not exist, a TRS channel targets a node with a
// matrix, a weights channel a node without morph targets, a sampler's input is empty, not
// finite or not strictly increasing, its output count does not match its input count (x3
// for CUBICSPLINE, x the morph target count for weights), or its interpolation is unknown.
// Channels with a path wavepath does not animate are skipped with a warning.
std::vector<Animation> readAnimations(const Context& ctx, const std::vector<size_t>& morphTargets);

// Reads skin `index`: its joints and inverse bind matrices (identity when absent). Throws,
// naming the skin, on a missing joint node or too few matrices.
Skin readSkin(const Context& ctx, size_t index);

}  // namespace wp::gltf
