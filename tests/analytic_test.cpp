// End-to-end renders with exact answers: analytic shapes under the constant white sky that
// lights scenes without emitters. A convex Lambertian surface of albedo a under a uniform sky
// of radiance 1 sends every bounce back to the sky, so it has radiance a exactly, with zero
// variance: any error in the sphere or plane intersection, their normals, the sky or the
// Lambert sampling shows up as a wrong pixel, not as noise.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// A plane (node-local +Y normal) with albedo 0.25, or a sphere of radius 1 with albedo 0.6
// above where the plane would be, seen from above by a camera looking straight down (-y).
// One shape per scene: a plane point sees a sphere above it, so with both the plane's
// radiance would depend on where its bounces go.
std::string sceneWith(const char* shapeNode) {
  return std::string(R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0, 1]}],
  "nodes": [
    )") + shapeNode + R"(,
    {"camera": 0, "translation": [0, 6, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]}
  ],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.01}}],
  "materials": [
    {"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.25, 0.25, 1]}, "extras": {"wavepath": {"bsdf": "lambert"}}},
    {"pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}, "extras": {"wavepath": {"bsdf": "lambert"}}}
  ]
})";
}

// Renders the shape in MIS and BSDF modes; returns the images.
std::vector<RadianceImage> renderShape(const char* name, const char* shapeNode) {
  std::filesystem::path dir = scratchDirectory(std::string("white-sky-") + name);
  std::ofstream(dir / "scene.gltf") << sceneWith(shapeNode);
  std::vector<RadianceImage> images;
  for (const char* mode : {"mis", "bsdf"}) {
    std::filesystem::path out = dir / (std::string(mode) + ".exr");
    RunResult r = runWavepath({"render", (dir / "scene.gltf").string(), "-o", out.string(), "--width", "33",
                               "--height", "33", "--spp", "4", "--mode", mode});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("constant white sky"), std::string::npos) << r.err;
    images.push_back(readExr(out));
  }
  return images;
}

TEST(WhiteSky, PlaneAndSphereReflectExactlyTheirAlbedo) {
  const int centre = 16 * 33 + 16;
  for (const RadianceImage& image :
       renderShape("plane", R"({"extras": {"wavepath": {"shape": "plane", "material": 0}}})")) {
    for (int pixel : {0, centre}) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(image.mean[pixel][c], 0.25f, 1e-5f) << "pixel " << pixel;
      }
      // Zero up to the rounding of the float sums the variance is computed from.
      EXPECT_LT(image.variance[pixel].x, 1e-6f * 0.25f * 0.25f);
    }
  }
  // The centre pixel sees the top of the sphere, a corner pixel the sky.
  for (const RadianceImage& image : renderShape(
           "sphere", R"({"translation": [0, 2, 0], "extras": {"wavepath": {"shape": "sphere", "radius": 1.0, "material": 1}}})")) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(image.mean[centre][c], 0.6f, 1e-5f);
      EXPECT_NEAR(image.mean[0][c], 1.0f, 1e-5f);
    }
    EXPECT_LT(image.variance[centre].x, 1e-6f * 0.6f * 0.6f);
  }
}

}  // namespace
}  // namespace wp::test
