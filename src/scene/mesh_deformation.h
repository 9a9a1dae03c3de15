// Morph targets and skinning of a mesh's vertices on the host (why the host: docs/animation.md).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "scene/scene.h"

namespace wp {

// Per-vertex displacements of one morph target (glTF POSITION and NORMAL deltas, zero
// where the target has none); normals may be empty.
struct MorphTarget {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;
};

// What it takes to deform one mesh: its rest vertices, its morph targets, and its skin
// weights, all aligned with the mesh's vertices.
struct MeshDeformation {
  std::vector<glm::vec3> restPositions;
  std::vector<glm::vec3> restNormals;  // empty when the mesh has no normals
  std::vector<glm::vec4> restTangents;  // TANGENT (w: bitangent sign); empty when the mesh has none
  std::vector<MorphTarget> targets;
  std::vector<glm::uvec4> joints;        // JOINTS_0: indices into the skin's joints; empty: no skin
  std::vector<glm::vec4> jointWeights;   // WEIGHTS_0, each summing to 1
};

// Sets mesh.positions and mesh.normals to the rest vertices plus the morph targets scaled by
// `weights` (one per target), then, when the mesh has a skin, moved by the blend of
// `jointMatrices` (per joint: the joint's world transform times its inverse bind matrix)
// with the vertex's joint weights. Normals go through the inverse transpose and are
// renormalised; zero normals stay zero (flat shading). Tangents are skinned as directions
// (morph targets' TANGENT deltas are not read), with the bitangent sign flipped where the
// blended joint transform mirrors, as baking does.
void deformMesh(const MeshDeformation& deformation, const std::vector<float>& weights,
                const std::vector<glm::mat4>& jointMatrices, Mesh& mesh);

}  // namespace wp
