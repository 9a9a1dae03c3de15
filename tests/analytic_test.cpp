// End-to-end renders with exact answers: analytic shapes under the constant white sky that
// lights scenes without emitters. A convex Lambertian surface of albedo a under a uniform sky
// of radiance 1 sends every bounce back to the sky, so it has radiance a exactly, with zero
// variance: any error in the sphere or plane intersection, their normals, the sky or the
// Lambert sampling shows up as a wrong pixel, not as noise.
#include <gtest/gtest.h>

#include <fstream>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// A plane (node-local +Y normal) with albedo 0.25 and, above it, a sphere of radius 1 with
// albedo 0.6, seen from above by a camera looking straight down (-y).
const char* kScene = R"({
  "asset": {"version": "2.0"},
  "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
  "nodes": [
    {"extras": {"wavepath": {"shape": "plane", "material": 0}}},
    {"translation": [0, 2, 0], "extras": {"wavepath": {"shape": "sphere", "radius": 1.0, "material": 1}}},
    {"camera": 0, "translation": [0, 6, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]}
  ],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.6, "znear": 0.01}}],
  "materials": [
    {"pbrMetallicRoughness": {"baseColorFactor": [0.25, 0.25, 0.25, 1]}},
    {"pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1]}}
  ]
})";

TEST(WhiteSky, PlaneAndSphereReflectExactlyTheirAlbedo) {
  std::filesystem::path dir = scratchDirectory("white-sky");
  std::ofstream(dir / "scene.gltf") << kScene;
  for (const char* mode : {"mis", "bsdf"}) {
    SCOPED_TRACE(mode);
    std::filesystem::path out = dir / (std::string(mode) + ".exr");
    RunResult r = runWavepath({"render", (dir / "scene.gltf").string(), "-o", out.string(), "--width", "33",
                               "--height", "33", "--spp", "4", "--mode", mode});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("constant white sky"), std::string::npos) << r.err;
    RadianceImage image = readExr(out);
    // The centre pixel sees the top of the sphere, a corner pixel the plane.
    glm::vec3 centre = image.mean[16 * 33 + 16];
    glm::vec3 corner = image.mean[0];
    for (int c = 0; c < 3; ++c) {
      EXPECT_NEAR(centre[c], 0.6f, 1e-5f);
      EXPECT_NEAR(corner[c], 0.25f, 1e-5f);
    }
    EXPECT_NEAR(image.variance[16 * 33 + 16].x, 0.0f, 1e-9f);
  }
}

}  // namespace
}  // namespace wp::test
