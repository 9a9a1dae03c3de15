// Sample glTF files that each show one feature (in the style of Khronos' sample models),
// written by the project's own code for the tests and for assets/samples.
#pragma once

#include <filesystem>

#include <glm/glm.hpp>

namespace wp::samples {

enum class Compression { None, Draco, Meshopt };

// A checker-textured UV sphere lit by a directional lamp (no sky needed), its vertex data
// plain FLOAT (None), compressed with Draco (KHR_draco_mesh_compression: 14-bit positions,
// 10-bit normals, 12-bit texture coordinates) or with meshoptimizer (EXT_meshopt_compression
// with KHR_mesh_quantization, as gltfpack writes it: 16-bit positions scaled by the node,
// 16-bit octahedral normals, 16-bit normalized texture coordinates, and a fallback buffer
// without data). Writes <dir>/compressed-{plain,draco,meshopt}.gltf and .bin.
std::filesystem::path writeCompressedSphere(const std::filesystem::path& dir, Compression compression);

// Khronos' SimpleSparseAccessor in spirit: a flat grid of which a sparse accessor lifts some
// vertices into two ridges, lit from the side; with `sparse` false the same positions are
// written out dense. Writes <dir>/sparse-grid.gltf or dense-grid.gltf, and its .bin.
std::filesystem::path writeSparseGrid(const std::filesystem::path& dir, bool sparse);

// A ground plane under the default white sky, tiled with a checker of one-texel squares
// whose sampler asks for mipmaps (minFilter LINEAR_MIPMAP_LINEAR), seen at a grazing angle
// so the texture is minified far beyond a texel per pixel: it shows what wavepath does
// instead of mipmapping (docs/scenes.md). Writes <dir>/minification.gltf and .bin.
std::filesystem::path writeMinificationPlane(const std::filesystem::path& dir);

// glTF alphaMode (samples/surface_samples.cpp). An orthographic camera looks down -z at a
// black quad of alphaMode MASK (x in [-2, 0], y in [-1, 1]) whose base colour texture is a
// 4x4 checker of alpha 1 and 0 (sampled NEAREST, texel (0, 0) opaque), and at a black pane
// of alphaMode BLEND (x in [0, 2]) whose alpha is 0.5 in baseColorFactor times 0.5 in
// COLOR_0; behind both, an emitter of radiance 1 fills the view. 2:1, so a 64x32 image has a
// texel per 8x8 pixels. Writes <dir>/alpha-coverage.gltf and .bin.
std::filesystem::path writeAlphaCoverage(const std::filesystem::path& dir);

// A sun shining along (1, -1, 0) onto a white floor (y = 0) through a black BLEND pane of
// alpha 0.25 at y = 1 over x < 0, which shades the floor at x in [-1, 1]; an orthographic
// camera looks straight down at x in [0, 2], z in [-0.5, 0.5] (2:1, past the pane's edge):
// the shadowed half should receive 0.75 of the lit half's light. Writes
// <dir>/alpha-shadow.gltf and .bin.
std::filesystem::path writeAlphaShadow(const std::filesystem::path& dir);

// KHR_texture_transform and texCoord, like Khronos' TextureTransformTest. The camera of
// writeAlphaCoverage looks at two quads that emit a 4x4 texture (transformTestTexel, sRGB,
// NEAREST, REPEAT) with radiance equal to its texels: on the left (x in [-2, 0]) on
// TEXCOORD_0 = ((x + 2) / 2, (1 - y) / 2) through offset kTransformOffset, rotation
// kTransformRotation and scale kTransformScale; on the right (x in [0, 2]) with texCoord 1,
// TEXCOORD_1 = (x / 2, (1 - y) / 2) (TEXCOORD_0 is 0.1 everywhere) through offset
// kSecondSetOffset. Writes <dir>/texture-transform.gltf and .bin.
std::filesystem::path writeTextureTransform(const std::filesystem::path& dir);
inline constexpr glm::vec2 kTransformOffset{0.25f, 0.5f};
inline constexpr float kTransformRotation = 0.3f;
inline constexpr glm::vec2 kTransformScale{1.5f, 2.0f};
inline constexpr glm::vec2 kSecondSetOffset{0.5f, 0.25f};
// Texel (x, y) of its texture, sRGB-encoded, a different colour each.
inline glm::u8vec3 transformTestTexel(int x, int y) {
  return glm::u8vec3(30 + 60 * x, 30 + 60 * y, 200 - 40 * x);
}

enum class MaterialExtension { Specular, Sheen, Clearcoat, Unlit };

// A row of four spheres of one material extension, its parameter stepping along the row
// (KHR_materials_specular: specularFactor 0 to 1 with an orange specularColorFactor over
// blue plastic; _sheen: sheenRoughnessFactor 0.2 to 0.8 of a pink sheen over dark blue cloth;
// _clearcoat: clearcoatRoughnessFactor 0, 0.2, 0.4 over rough red plastic, then 0.05 with a
// rippled clearcoatNormalTexture; _unlit: four base colours), lit by a directional lamp. With
// `withExtension` false the same file without the extension, for comparison. Writes
// <dir>/<extension>-spheres.gltf (or <extension>-spheres-without.gltf) and its .bin.
std::filesystem::path writeMaterialSpheres(const std::filesystem::path& dir, MaterialExtension extension,
                                           bool withExtension);

// Writes every sample into `dir`.
void writeAllSamples(const std::filesystem::path& dir);

}  // namespace wp::samples
