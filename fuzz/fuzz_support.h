// What the fuzz targets share: a scratch file per process for the bytes under test, and the
// checks that turn a silently wrong result (a non-finite number) into a reported finding.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <vector>

namespace wp {
struct Scene;
struct GpuScene;
struct EnvironmentMap;
}  // namespace wp

namespace wp::fuzz {

// Writes the input to `name` in this process's scratch directory (under TMPDIR) and returns
// its path; the loaders then read it as they read a user's file.
std::filesystem::path writeInput(const char* name, const uint8_t* data, size_t size);

// Abort (a finding) with `what` unless every number the renderer would use is finite: vertex
// data, materials, camera, sky, and the packed GPU arrays.
void checkFinite(const Scene& scene, const GpuScene& gpuScene);
void checkFinite(const EnvironmentMap& sky);

// A .glb of one quad with TEXCOORD_0 whose material uses `image` (any bytes, declared PNG) as
// its base colour, emissive and normal texture.
std::vector<uint8_t> texturedQuadGlb(const uint8_t* image, size_t imageSize);

// Loads the scene in `file` as `wavepath render` does, poses it at 0.5 s when animated, packs
// it for the GPU and checks the result. A wp::Error (bad input, said in one line) is the
// expected outcome for most inputs; anything else escaping is a finding.
void loadAndCheck(const std::filesystem::path& file);

}  // namespace wp::fuzz
