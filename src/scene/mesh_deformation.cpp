// Morph targets and skinning of a mesh's vertices on the host.
#include "scene/mesh_deformation.h"

namespace wp {

namespace {

glm::vec3 unitOrZero(const glm::vec3& n) {
  const float length = glm::length(n);
  return length > 0.0f ? n / length : glm::vec3(0.0f);
}

// The inverse transpose up to a positive factor (the cofactor matrix times the sign of the
// determinant), which is all a normal that is renormalised needs: cheaper than an inverse,
// and without a division that a collapsed joint would turn into NaN.
glm::mat3 normalMatrix(const glm::mat3& m) {
  const glm::mat3 cofactor(glm::cross(m[1], m[2]), glm::cross(m[2], m[0]), glm::cross(m[0], m[1]));
  return glm::determinant(m) < 0.0f ? -cofactor : cofactor;
}

}  // namespace

void deformMesh(const MeshDeformation& d, const std::vector<float>& weights,
                const std::vector<glm::mat4>& jointMatrices, Mesh& mesh) {
  mesh.positions = d.restPositions;
  mesh.normals = d.restNormals;
  mesh.tangents = d.restTangents;
  const bool hasNormals = !mesh.normals.empty();
  for (size_t t = 0; t < d.targets.size(); ++t) {
    const float w = weights[t];
    if (w == 0.0f) continue;
    const MorphTarget& target = d.targets[t];
    for (size_t v = 0; v < mesh.positions.size(); ++v) mesh.positions[v] += w * target.positions[v];
    if (hasNormals && !target.normals.empty()) {
      for (size_t v = 0; v < mesh.normals.size(); ++v) {
        // A zero normal marks flat shading; a delta must not turn it into a direction.
        if (d.restNormals[v] != glm::vec3(0.0f)) mesh.normals[v] += w * target.normals[v];
      }
    }
  }
  if (d.joints.empty()) {
    if (hasNormals) {
      for (glm::vec3& n : mesh.normals) n = unitOrZero(n);
    }
    return;
  }
  for (size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::uvec4 j = d.joints[v];
    const glm::vec4 w = d.jointWeights[v];
    const glm::mat4 skin = w.x * jointMatrices[j.x] + w.y * jointMatrices[j.y] + w.z * jointMatrices[j.z] +
                           w.w * jointMatrices[j.w];
    mesh.positions[v] = glm::vec3(skin * glm::vec4(mesh.positions[v], 1.0f));
    if (hasNormals) mesh.normals[v] = unitOrZero(normalMatrix(glm::mat3(skin)) * mesh.normals[v]);
    if (!mesh.tangents.empty()) {
      const glm::vec4 t = d.restTangents[v];
      const float sign = glm::determinant(glm::mat3(skin)) < 0.0f ? -t.w : t.w;
      mesh.tangents[v] = glm::vec4(unitOrZero(glm::mat3(skin) * glm::vec3(t)), sign);
    }
  }
}

}  // namespace wp
