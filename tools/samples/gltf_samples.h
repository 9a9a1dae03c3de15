// Sample glTF files that each show one feature (in the style of Khronos' sample models),
// written by the project's own code for the tests and for assets/samples.
#pragma once

#include <filesystem>

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
