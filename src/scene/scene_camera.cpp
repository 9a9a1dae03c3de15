// Scene cameras: from a glTF camera node, or framed automatically around the scene.
#include "scene/scene_camera.h"

#include <cmath>
#include <limits>

namespace wp {

namespace {

constexpr float kFramingMargin = 1.1f;

struct Bounds {
  glm::vec3 lo{std::numeric_limits<float>::max()};
  glm::vec3 hi{-std::numeric_limits<float>::max()};

  bool empty() const { return lo.x > hi.x; }
  void add(const glm::vec3& p) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  // Adds this box moved by `m` (its 8 transformed corners; exact for unrotated instances).
  void addTransformed(const Bounds& box, const glm::mat4& m) {
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p((corner & 1) ? box.hi.x : box.lo.x, (corner & 2) ? box.hi.y : box.lo.y,
                        (corner & 4) ? box.hi.z : box.lo.z);
      add(glm::vec3(m * glm::vec4(p, 1.0f)));
    }
  }
};

// Object-space bounds of the vertices the triangles use, once per mesh however many
// instances it has.
Bounds meshBounds(const Mesh& mesh) {
  Bounds bounds;
  for (uint32_t index : mesh.indices) bounds.add(mesh.positions[index]);
  return bounds;
}

Bounds sceneBounds(const Scene& scene) {
  std::vector<Bounds> perMesh;
  for (const Mesh& mesh : scene.meshes) perMesh.push_back(meshBounds(mesh));
  Bounds bounds;
  for (const MeshInstance& instance : scene.instances) {
    if (!perMesh[instance.mesh].empty()) bounds.addTransformed(perMesh[instance.mesh], instance.objectToWorld);
  }
  for (const Sphere& sphere : scene.spheres) {
    // The exact box of an ellipsoid: per axis, the length of that row of the linear part.
    const glm::mat3 m(sphere.objectToWorld);
    const glm::vec3 halfExtent(glm::length(glm::vec3(m[0][0], m[1][0], m[2][0])),
                               glm::length(glm::vec3(m[0][1], m[1][1], m[2][1])),
                               glm::length(glm::vec3(m[0][2], m[1][2], m[2][2])));
    const glm::vec3 centre(sphere.objectToWorld[3]);
    bounds.add(centre - halfExtent);
    bounds.add(centre + halfExtent);
  }
  return bounds;
}

}  // namespace

std::optional<Camera> cameraFromNode(const glm::mat4& world, float yfov, float aspectRatio) {
  const glm::vec3 forward(world * glm::vec4(0.0f, 0.0f, -1.0f, 0.0f));
  const glm::vec3 up(world * glm::vec4(0.0f, 1.0f, 0.0f, 0.0f));
  if (!(glm::length(forward) > 0.0f)) return std::nullopt;
  Camera camera;
  camera.position = glm::vec3(world * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
  camera.forward = glm::normalize(forward);
  const glm::vec3 orthogonalUp = up - glm::dot(up, camera.forward) * camera.forward;
  // Relative test: a shear can leave up almost parallel to forward.
  if (!(glm::length(orthogonalUp) > 1e-6f * glm::length(up))) return std::nullopt;
  camera.up = glm::normalize(orthogonalUp);
  camera.yfov = yfov;
  camera.aspectRatio = aspectRatio;
  return camera;
}

Camera frameScene(const Scene& scene) {
  const Bounds bounds = sceneBounds(scene);
  glm::vec3 centre(0.0f);
  float radius = 1.0f;
  if (!bounds.empty()) {
    centre = 0.5f * (bounds.lo + bounds.hi);
    radius = 0.5f * glm::length(bounds.hi - bounds.lo);
    // A single point (all triangles degenerate at one spot) still needs a distance.
    if (!(radius > 0.0f)) radius = 1.0f;
  }
  Camera camera;
  camera.yfov = kFramingYfov;
  camera.aspectRatio = 0.0f;
  camera.forward = glm::vec3(0.0f, 0.0f, -1.0f);
  camera.up = glm::vec3(0.0f, 1.0f, 0.0f);
  camera.position = centre + glm::vec3(0.0f, 0.0f, kFramingMargin * radius / std::sin(0.5f * kFramingYfov));
  return camera;
}

}  // namespace wp
