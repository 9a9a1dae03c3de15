// End-to-end renders with exact answers: analytic shapes under the constant white sky that
// lights scenes without emitters. A convex Lambertian surface of albedo a under a uniform sky
// of radiance 1 sends every bounce back to the sky, so it has radiance a exactly, with zero
// variance: any error in the sphere or plane intersection, their normals, the sky or the
// Lambert sampling shows up as a wrong pixel, not as noise.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
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

const char* kPlane = R"({"extras": {"wavepath": {"shape": "plane", "material": 0}}})";
const char* kSphere =
    R"({"translation": [0, 2, 0], "extras": {"wavepath": {"shape": "sphere", "radius": 1.0, "material": 1}}})";
constexpr int kCentre = 16 * 33 + 16;

RadianceImage renderShape(const char* name, const char* shapeNode, const std::string& mode, int spp) {
  std::filesystem::path dir = scratchDirectory(std::string("white-sky-") + name);
  std::ofstream(dir / "scene.gltf") << sceneWith(shapeNode);
  std::filesystem::path out = dir / (mode + ".exr");
  RunResult r = runWavepath({"render", (dir / "scene.gltf").string(), "-o", out.string(), "--width", "33", "--height",
                             "33", "--spp", std::to_string(spp), "--mode", mode});
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("constant white sky"), std::string::npos) << r.err;
  return readExr(out);
}

// BSDF sampling alone carries no light-sampling weight: every path gathers exactly albedo * 1.
TEST(WhiteSky, BsdfSampledPlaneAndSphereReflectExactlyTheirAlbedo) {
  RadianceImage plane = renderShape("plane", kPlane, "bsdf", 4);
  for (int pixel : {0, kCentre}) {
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(plane.mean[pixel][c], 0.25f, 1e-5f) << "pixel " << pixel;
    }
    // Zero up to the rounding of the float sums the variance is computed from.
    EXPECT_LT(plane.variance[pixel].x, 1e-6f * 0.25f * 0.25f);
  }
  // The centre pixel sees the top of the sphere, a corner pixel the sky.
  RadianceImage sphere = renderShape("sphere", kSphere, "bsdf", 4);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(sphere.mean[kCentre][c], 0.6f, 1e-5f);
    EXPECT_NEAR(sphere.mean[0][c], 1.0f, 1e-5f);
  }
  EXPECT_LT(sphere.variance[kCentre].x, 1e-6f * 0.6f * 0.6f);
}

// With the sky light-sampled (MIS, NEE only) the estimate has variance but the same mean:
// the 5x5 block at the centre (all on the sphere) averages to the albedo within 4 standard
// errors, which are kept under 1% of it so that a wrong pdf or weight cannot hide.
TEST(WhiteSky, LightSampledSkyGivesTheSameAlbedo) {
  for (const char* mode : {"mis", "nee"}) {
    SCOPED_TRACE(mode);
    RadianceImage image = renderShape("sphere", kSphere, mode, 1024);
    double mean = 0.0, variance = 0.0;
    for (int y = 14; y <= 18; ++y) {
      for (int x = 14; x <= 18; ++x) {
        mean += image.mean[y * 33 + x].x / 25.0;
        variance += image.variance[y * 33 + x].x / (25.0 * 25.0);
      }
    }
    double standardError = std::sqrt(variance);
    EXPECT_LT(standardError, 0.006);
    EXPECT_NEAR(mean, 0.6, std::max(4.0 * standardError, 1e-6));
  }
}

}  // namespace
}  // namespace wp::test
