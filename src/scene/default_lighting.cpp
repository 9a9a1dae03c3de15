// What lights a scene whose user named no sky.
#include "scene/default_lighting.h"

#include <glm/glm.hpp>

#include "shaders/common/sampling.h"

namespace wp {

namespace {

bool hasArea(const Mesh& mesh, size_t triangle) {
  const glm::vec3& a = mesh.positions[mesh.indices[3 * triangle]];
  const glm::vec3& b = mesh.positions[mesh.indices[3 * triangle + 1]];
  const glm::vec3& c = mesh.positions[mesh.indices[3 * triangle + 2]];
  return glm::length(glm::cross(b - a, c - a)) > 0.0f;
}

// The brightest emitted luminance of any emitter the scene places, and how many emitters
// (triangles, spheres, planes) emit at all. A texture only darkens its factor.
struct Emitters {
  size_t count = 0;
  float brightest = 0.0f;

  void add(const Material& material, size_t n) {
    if (!material.isEmissive() || n == 0) return;
    count += n;
    brightest = std::max(brightest, gpu::luminance(material.emission));
  }
};

Emitters emittersOf(const Scene& scene) {
  std::vector<Emitters> perMesh(scene.meshes.size());
  for (size_t m = 0; m < scene.meshes.size(); ++m) {
    const Mesh& mesh = scene.meshes[m];
    for (size_t t = 0; t < mesh.triangleCount(); ++t) {
      if (hasArea(mesh, t)) perMesh[m].add(scene.materials[mesh.materials[t]], 1);
    }
  }
  Emitters all;
  for (const MeshInstance& instance : scene.instances) {
    all.count += perMesh[instance.mesh].count;
    all.brightest = std::max(all.brightest, perMesh[instance.mesh].brightest);
  }
  for (const Sphere& sphere : scene.spheres) all.add(scene.materials[sphere.material], 1);
  for (const Plane& plane : scene.planes) all.add(scene.materials[plane.material], 1);
  return all;
}

std::string countOf(size_t n, const char* what) {
  return std::to_string(n) + " " + what + (n == 1 ? "" : "s");
}

}  // namespace

DefaultLighting chooseDefaultLighting(const Scene& scene, const std::string& file) {
  const Emitters emitters = emittersOf(scene);
  const bool brightEmitters = emitters.brightest > kDefaultSkyRadiance;
  DefaultLighting lighting;
  if (!scene.lights.empty() || brightEmitters) {
    std::string by;
    if (!scene.lights.empty()) by = countOf(scene.lights.size(), "lamp");
    if (brightEmitters) by += std::string(by.empty() ? "" : " and ") + "emitters brighter than a white sky";
    lighting.note = file + " is lit by its " + by + ", so it gets no sky; --sky-color R,G,B or --sky FILE adds one";
    return lighting;
  }
  lighting.whiteSky = true;
  lighting.note = emitters.count == 0
                      ? file + " has no lamps or emitters: lighting it with a constant white sky (--sky-color R,G,B or "
                               "--sky FILE to change it, --sky none for none)"
                      : file + " has no lamps, and its emitters are no brighter than a white sky (they glow rather "
                               "than light): lighting it with a constant white sky too; --sky none turns it off";
  return lighting;
}

}  // namespace wp
