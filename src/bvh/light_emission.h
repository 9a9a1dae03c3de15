// The mean emitted radiance of a (possibly textured) emissive triangle, for light selection.
#pragma once

#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "shaders/common/layout.h"

namespace wp {

// The mean over the triangle of texturedEmission (texture.h, the code the GPU runs for hits
// and light samples): `factor` times texture `texture` (WP_INVALID: none) at the texture
// coordinates of `shading`. Estimated as the average at the centroids of n x n equal
// sub-triangles, with n about the footprint's size in texels, from 4 to 32, so a triangle
// over a black region gets a mean near 0. Requires `texture` to index `textures`.
glm::vec3 meanEmission(const std::vector<gpu::GpuTexture>& textures, const std::vector<uint32_t>& texels,
                       const gpu::GpuTriangleShading& shading, glm::vec3 factor, uint32_t texture);

}  // namespace wp
