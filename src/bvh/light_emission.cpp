// The mean emitted radiance of a (possibly textured) emissive triangle, for light selection.
#include "bvh/light_emission.h"

#include <algorithm>
#include <cmath>

#include "shaders/common/texture.h"

namespace wp {

glm::vec3 meanEmission(const std::vector<gpu::GpuTexture>& textures, const std::vector<uint32_t>& texels,
                       const gpu::GpuTriangleShading& shading, glm::vec3 factor, uint32_t texture) {
  if (texture == WP_INVALID || !gpu::hasUv(shading)) {
    return factor;
  }
  const glm::vec2 texelsPerUnit(gpu::textureWidth(textures[texture]), gpu::textureHeight(textures[texture]));
  const glm::vec2 uv[3] = {gpu::uvAt(shading, {0.0f, 0.0f}), gpu::uvAt(shading, {1.0f, 0.0f}),
                           gpu::uvAt(shading, {0.0f, 1.0f})};
  float extent = 0.0f;
  for (int k = 0; k < 3; ++k) {
    extent = std::max(extent, glm::length((uv[(k + 1) % 3] - uv[k]) * texelsPerUnit));
  }
  const int n = std::clamp(static_cast<int>(std::ceil(extent)), 4, 32);
  gpu::DeviceBuffers buffers{};
  buffers.textures = textures.data();
  buffers.texels = texels.data();
  auto at = [&](float b1, float b2) {
    return gpu::texturedEmission(buffers, factor, texture, true, gpu::uvAt(shading, {b1, b2}));
  };
  // Splitting each edge into n parts makes n (n + 1) / 2 upright sub-triangles, with corners
  // (i, j), (i + 1, j), (i, j + 1) in units of 1 / n, and n (n - 1) / 2 inverted ones.
  glm::vec3 sum(0.0f);
  const float step = 1.0f / static_cast<float>(n);
  for (int i = 0; i < n; ++i) {
    for (int j = 0; i + j < n; ++j) {
      sum += at((static_cast<float>(i) + 1.0f / 3.0f) * step, (static_cast<float>(j) + 1.0f / 3.0f) * step);
      if (i + j < n - 1) {
        sum += at((static_cast<float>(i) + 2.0f / 3.0f) * step, (static_cast<float>(j) + 2.0f / 3.0f) * step);
      }
    }
  }
  return sum / static_cast<float>(n * n);
}

}  // namespace wp
