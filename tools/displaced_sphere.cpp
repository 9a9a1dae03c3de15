// The benchmarks' test mesh: a UV sphere with a bumpy, optionally moving, displacement.
#include "displaced_sphere.h"

#include <algorithm>
#include <cmath>

namespace wp::bench {

Mesh displacedSphere(size_t triangles, float phase) {
  int rings = std::max(2, static_cast<int>(std::sqrt(static_cast<double>(triangles) / 4.0)));
  int segments = 2 * rings;
  Mesh mesh;
  mesh.name = "displaced sphere";
  for (int ring = 0; ring <= rings; ++ring) {
    for (int segment = 0; segment <= segments; ++segment) {
      float theta = 3.14159265f * static_cast<float>(ring) / static_cast<float>(rings);
      float phi = 6.28318531f * static_cast<float>(segment) / static_cast<float>(segments);
      glm::vec3 dir(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      float r = 1.0f + 0.1f * std::sin(7.0f * dir.x + phase) * std::sin(5.0f * dir.y + 1.0f) +
                0.03f * std::sin(31.0f * dir.z + 2.0f * dir.x) + 0.01f * std::sin(97.0f * dir.y);
      mesh.positions.push_back(r * dir);
    }
  }
  auto vertex = [&](int ring, int segment) { return static_cast<uint32_t>(ring * (segments + 1) + segment); };
  for (int ring = 0; ring < rings; ++ring) {
    for (int segment = 0; segment < segments; ++segment) {
      uint32_t a = vertex(ring, segment), b = vertex(ring, segment + 1);
      uint32_t c = vertex(ring + 1, segment), d = vertex(ring + 1, segment + 1);
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});
    }
  }
  mesh.materials.assign(mesh.triangleCount(), 0);
  return mesh;
}

}  // namespace wp::bench
