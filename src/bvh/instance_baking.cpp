// Baking of single-use meshes into one world-space mesh.
#include "bvh/instance_baking.h"

#include <utility>

namespace wp {

namespace {

// Appends a mesh's texture coordinates `source` (of the vertices from `base` to `end` of the
// baked mesh) to the baked mesh's `target`, zero-filled where either side has none.
void appendTexCoords(const std::vector<glm::vec2>& source, uint32_t base, size_t end, std::vector<glm::vec2>& target) {
  if (source.empty() && target.empty()) return;
  target.resize(base, glm::vec2(0.0f));
  if (source.empty()) {
    target.resize(end, glm::vec2(0.0f));
  } else {
    target.insert(target.end(), source.begin(), source.end());
  }
}

}  // namespace

Scene bakeSingleUseMeshes(const Scene& scene) {
  std::vector<uint32_t> uses(scene.meshes.size(), 0);
  for (const MeshInstance& inst : scene.instances) {
    ++uses[inst.mesh];
  }
  Scene out = scene;
  out.meshes.clear();
  out.instances.clear();
  Mesh baked;
  baked.name = "single-use meshes in world space";
  std::vector<uint32_t> remap(scene.meshes.size(), UINT32_MAX);
  for (const MeshInstance& inst : scene.instances) {
    const Mesh& mesh = scene.meshes[inst.mesh];
    float det = glm::determinant(glm::mat3(inst.objectToWorld));
    if (uses[inst.mesh] != 1 || det == 0.0f || inst.animated || mesh.deforming || inst.objectToWorldAtClose) {
      // Shared meshes stay instanced; singular transforms are left for the packer to report;
      // animated and moving ones stay apart so that a new pose needs no re-baking and motion
      // blur can move them.
      if (remap[inst.mesh] == UINT32_MAX) {
        remap[inst.mesh] = uint32_t(out.meshes.size());
        out.meshes.push_back(mesh);
      }
      MeshInstance& kept = out.instances.emplace_back(inst);
      kept.mesh = remap[inst.mesh];
      continue;
    }
    uint32_t base = uint32_t(baked.positions.size());
    for (const glm::vec3& p : mesh.positions) {
      baked.positions.push_back(glm::vec3(inst.objectToWorld * glm::vec4(p, 1.0f)));
    }
    if (!mesh.normals.empty()) {
      // Normals go through the inverse transpose; zero ones stay zero (flat shading).
      glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(inst.objectToWorld)));
      baked.normals.resize(base, glm::vec3(0.0f));
      for (const glm::vec3& n : mesh.normals) {
        glm::vec3 m = normalMatrix * n;
        baked.normals.push_back(n == glm::vec3(0.0f) ? n : glm::normalize(m));
      }
    } else if (!baked.normals.empty()) {
      baked.normals.resize(baked.positions.size(), glm::vec3(0.0f));
    }
    if (!mesh.tangents.empty()) {
      // Tangents are directions on the surface, so they take the transform itself. glTF's
      // bitangent is w cross(normal, tangent), and a mirroring transform (det < 0) turns
      // that cross product around relative to the transformed bitangent: flip w with it.
      baked.tangents.resize(base, glm::vec4(0.0f));
      for (const glm::vec4& t : mesh.tangents) {
        glm::vec3 m = glm::mat3(inst.objectToWorld) * glm::vec3(t);
        bool zero = glm::vec3(t) == glm::vec3(0.0f);
        baked.tangents.push_back(zero ? t : glm::vec4(glm::normalize(m), det < 0.0f ? -t.w : t.w));
      }
    } else if (!baked.tangents.empty()) {
      baked.tangents.resize(baked.positions.size(), glm::vec4(0.0f));
    }
    if (!mesh.colors.empty() || !baked.colors.empty()) {
      baked.colors.resize(base, glm::vec4(1.0f));
      if (mesh.colors.empty()) {
        baked.colors.resize(baked.positions.size(), glm::vec4(1.0f));
      } else {
        baked.colors.insert(baked.colors.end(), mesh.colors.begin(), mesh.colors.end());
      }
    }
    appendTexCoords(mesh.uvs, base, baked.positions.size(), baked.uvs);
    appendTexCoords(mesh.uvs1, base, baked.positions.size(), baked.uvs1);
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      uint32_t a = mesh.indices[3 * t], b = mesh.indices[3 * t + 1], c = mesh.indices[3 * t + 2];
      if (det < 0.0f) {
        std::swap(b, c);
      }
      baked.indices.insert(baked.indices.end(), {base + a, base + b, base + c});
    }
    baked.materials.insert(baked.materials.end(), mesh.materials.begin(), mesh.materials.end());
  }
  if (!baked.indices.empty()) {
    out.instances.push_back({uint32_t(out.meshes.size()), glm::mat4(1.0f)});
    out.meshes.push_back(std::move(baked));
  }
  return out;
}

}  // namespace wp
