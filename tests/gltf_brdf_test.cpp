// End-to-end renders of glTF's metallic-roughness BRDF on both backends: the white furnace of
// its dielectric and metal and of the material extensions, and the Cornell box written as
// exporters write a matte surface, against Cycles' Lambertian reference.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "image/image_io.h"
#include "support/image_stats.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

using Backends = ::testing::TestWithParam<std::string>;

// A unit sphere with one material under a constant white sky, seen head-on by an orthographic
// camera whose view is the sphere's bounding square. A convex sphere never sees itself, so
// each pixel is the material's directional albedo at that pixel's angle times the sky's 1.
std::string furnaceScene(const std::string& material) {
  return std::string(R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
  "extensionsUsed": ["KHR_materials_specular", "KHR_materials_sheen", "KHR_materials_clearcoat",
                     "KHR_materials_unlit"],
  "nodes": [{"extras": {"wavepath": {"shape": "sphere", "radius": 1.0, "material": 0}}},
            {"camera": 0, "translation": [0, 0, 5]}],
  "cameras": [{"type": "orthographic", "orthographic": {"xmag": 1, "ymag": 1, "znear": 0.1, "zfar": 10}}],
  "materials": [)") + material + "]}";
}

// A white glTF material, with `extensions` (JSON members) when not empty.
std::string whiteMaterial(double metallic, double roughness, const char* extensions = "") {
  char material[640];
  std::snprintf(material, sizeof material,
                R"({"pbrMetallicRoughness": {"baseColorFactor": [1, 1, 1, 1], "metallicFactor": %g,
                     "roughnessFactor": %g}, "extensions": {%s}})",
                metallic, roughness, extensions);
  return material;
}

struct FurnaceResult {
  double mean = 0.0;
  double standardError = 0.0;
};

// The mean over the pixels whose whole footprint lies on the sphere's disc, and its error.
FurnaceResult furnace(const std::string& backend, const std::string& name, const std::string& material) {
  const std::filesystem::path dir = scratchDirectory("furnace-" + backend + "-" + name);
  std::ofstream(dir / "scene.gltf") << furnaceScene(material);
  // Pixels wholly on the disc reach out to 97% of its radius at 64x64, so the grazing ring
  // where rough single scattering loses most is in the mean (at 20x20 a fifth of it was not).
  const int size = 64;
  const RunResult r = runWavepath({"render", (dir / "scene.gltf").string(), "-o", (dir / "out.exr").string(),
                                   "--width", std::to_string(size), "--height", std::to_string(size), "--spp", "64",
                                   "--backend", backend});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  const RadianceImage image = readExr(dir / "out.exr");
  FurnaceResult result;
  double varianceSum = 0.0;
  int count = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      // The pixel's corner farthest from the centre, in units of the radius.
      const double fx = std::max(std::abs(2.0 * x / size - 1.0), std::abs(2.0 * (x + 1) / size - 1.0));
      const double fy = std::max(std::abs(2.0 * y / size - 1.0), std::abs(2.0 * (y + 1) / size - 1.0));
      if (fx * fx + fy * fy >= 1.0) continue;
      const size_t i = size_t(y) * size + x;
      result.mean += image.mean[i].g;
      varianceSum += image.variance[i].g;
      ++count;
    }
  }
  result.mean /= count;
  result.standardError = std::sqrt(varianceSum) / count;
  return result;
}

// The white furnace of glTF's materials: a dielectric with base colour 1 at roughness 0,
// 0.25, 0.5 and 1, and a metal of F0 = 1 at roughness 0.5 and 1. Energy compensation gives back
// what single-scattering GGX loses, so each reflects 1 to within the interpolation error of
// its albedo tables (bsdf_test): the test asks for at least 0.99, tighter than the [0.95, 1]
// the issue asks for, because without the dielectric's compensation roughness 1 still gives
// 0.953 here (without the metal's, about 0.4). Noise is below 1e-3 at 64 spp.
TEST_P(Backends, WhiteFurnaceReflectsEverything) {
  const struct {
    double metallic, roughness;
  } cases[] = {{0, 0}, {0, 0.25}, {0, 0.5}, {0, 1}, {1, 0.5}, {1, 1}};
  for (const auto& c : cases) {
    const std::string name = std::to_string(int(c.metallic)) + "-" + std::to_string(int(std::lround(c.roughness * 100)));
    const FurnaceResult result = furnace(GetParam(), name, whiteMaterial(c.metallic, c.roughness));
    std::printf("%s, roughness %.2f: reflects %.4f (standard error %.5f)\n", c.metallic > 0 ? "metal" : "dielectric",
                c.roughness, result.mean, result.standardError);
    SCOPED_TRACE((c.metallic > 0 ? "metal, roughness " : "dielectric, roughness ") + std::to_string(c.roughness));
    EXPECT_GE(result.mean, 0.99);
    EXPECT_LE(result.mean, 1.0 + 4.0 * result.standardError);
  }
}

// The white furnace of the layered extensions over a white base of roughness 0.5: each
// reflects at most 1, and as much as its model keeps, so each bound also fails when the layer
// is dropped (the base alone gives 1.00) or lets the base through unscaled (above 1).
// KHR_materials_specular's weaker layer hands what it does not reflect to the base, so it
// keeps 1 as the plain dielectric does (1.0024 here). A sheen or a coat lets through to the
// base only what it does not reflect, in the min form of albedo scaling that the sheen
// extension gives (material.h), which is conservative where the two directions' albedos
// differ, most at grazing angles: a white sheen of roughness 0.5 keeps 0.936, a coat of
// roughness 0.3 0.976 over the dielectric and 0.979 over a white metal (both backends; noise
// below 1e-3). An unlit sphere of base colour 0.5 shows exactly 0.5: its colour, and none
// of the sky it would reflect if it scattered.
TEST_P(Backends, WhiteFurnaceOfTheMaterialExtensions) {
  const struct {
    const char* name;
    std::string material;
    double atLeast, atMost;
  } cases[] = {
      {"specular", whiteMaterial(0, 0.5, R"("KHR_materials_specular": {"specularFactor": 0.5})"), 0.99, 1.0},
      {"sheen", whiteMaterial(0, 0.5, R"("KHR_materials_sheen": {"sheenColorFactor": [1, 1, 1],
                                         "sheenRoughnessFactor": 0.5})"), 0.92, 0.95},
      {"clearcoat", whiteMaterial(0, 0.5, R"("KHR_materials_clearcoat": {"clearcoatFactor": 1,
                                             "clearcoatRoughnessFactor": 0.3})"), 0.965, 0.99},
      {"clearcoat-metal", whiteMaterial(1, 0.5, R"("KHR_materials_clearcoat": {"clearcoatFactor": 1,
                                                   "clearcoatRoughnessFactor": 0.3})"), 0.965, 0.99},
      {"unlit", R"({"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]},
                    "extensions": {"KHR_materials_unlit": {}}})", 0.5 - 1e-6, 0.5 + 1e-6},
  };
  for (const auto& c : cases) {
    const FurnaceResult result = furnace(GetParam(), c.name, c.material);
    std::printf("%s: reflects %.4f (standard error %.5f)\n", c.name, result.mean, result.standardError);
    SCOPED_TRACE(c.name);
    EXPECT_GE(result.mean, c.atLeast);
    EXPECT_LE(result.mean, c.atMost + 4.0 * result.standardError);
  }
}

ImageMean cornellMean(const std::string& backend, const std::filesystem::path& scene, const std::string& name) {
  const std::filesystem::path dir = scratchDirectory("cornell-" + name + "-" + backend);
  const RunResult r = runWavepath({"render", scene.string(), "-o", (dir / "out.exr").string(), "--width", "64",
                                   "--height", "64", "--spp", "128", "--max-depth", "8", "--backend", backend});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  return imageMean(readExr(dir / "out.exr"));
}

// tests/data/cornell-plain.gltf is the Cornell box as exporters write a matte wall
// (metallicFactor 0, roughnessFactor 1, no extras); cornell-cycles-64.exr is Cycles' 4096-spp
// Lambertian render of it box-averaged to 64x64 (tests/data/README.md). glTF's BRDF puts a weak
// white specular layer over the Lambertian base, so each channel's mean over the image lies
// within 5% of the reference (it renders at 1.016, 1.017, 1.019; the seed's Disney base gave
// 0.69, 0.80, 0.85); the same box marked Lambertian (assets/cornell-box.gltf) is within 1%,
// which is 10 standard errors of the render's mean and above the reference's own noise.
TEST_P(Backends, PlainGltfCornellBoxIsWithinFivePercentOfTheLambertianReference) {
  const RadianceImage reference = readExr(sourceDirectory() / "tests" / "data" / "cornell-cycles-64.exr");
  glm::dvec3 expected(0.0);
  for (const glm::vec3& pixel : reference.mean) expected += glm::dvec3(pixel) / double(reference.mean.size());
  const ImageMean plain = cornellMean(GetParam(), sourceDirectory() / "tests" / "data" / "cornell-plain.gltf", "plain");
  const ImageMean lambert = cornellMean(GetParam(), sourceDirectory() / "assets" / "cornell-box.gltf", "lambert");
  for (int c = 0; c < 3; ++c) {
    std::printf("channel %d: plain glTF %.4f, Lambertian %.4f of the reference\n", c, plain.mean[c] / expected[c],
                lambert.mean[c] / expected[c]);
    EXPECT_NEAR(plain.mean[c] / expected[c], 1.0, 0.05) << "channel " << c;
    EXPECT_NEAR(lambert.mean[c] / expected[c], 1.0, 0.01) << "channel " << c;
  }
}

INSTANTIATE_TEST_SUITE_P(Backend, Backends, ::testing::Values("vulkan", "opencl"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace wp::test
