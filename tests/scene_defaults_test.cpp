// What wavepath chooses when a file leaves it open, through the real command line: the light
// (the default-lighting rule, --sky none, --sky-color) and the note on an almost black image,
// the camera of a file without one (from outside, or from inside a room lit from within),
// and the one error line of a --camera or --scene the file does not have.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "image/image_io.h"
#include "support/gltf_writer.h"
#include "support/image_stats.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// An axis-aligned box from lo to hi, 12 triangles wound so that their fronts face `inwards`
// or outwards.
TestMesh box(glm::vec3 lo, glm::vec3 hi, bool inwards, int material) {
  TestMesh mesh;
  mesh.material = material;
  for (int corner = 0; corner < 8; ++corner) {
    mesh.positions.push_back({corner & 1 ? hi.x : lo.x, corner & 2 ? hi.y : lo.y, corner & 4 ? hi.z : lo.z});
  }
  // Each face's corners counter-clockwise seen from outside.
  const uint32_t faces[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& f : faces) {
    const uint32_t a = f[0], b = inwards ? f[3] : f[1], c = f[2], d = inwards ? f[1] : f[3];
    mesh.indices.insert(mesh.indices.end(), {a, b, c, a, c, d});
  }
  return mesh;
}

// A small emissive square just under y = ceiling, facing down.
TestMesh ceilingLamp(float ceiling, int material) {
  TestMesh mesh;
  mesh.material = material;
  const float y = ceiling - 0.01f;
  mesh.positions = {{-0.3f, y, -0.3f}, {0.3f, y, -0.3f}, {0.3f, y, 0.3f}, {-0.3f, y, 0.3f}};
  mesh.indices = {0, 1, 2, 0, 2, 3};
  return mesh;
}

RunResult render(const std::filesystem::path& scene, const std::filesystem::path& out,
                 const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args = {"render", scene.string(), "-o", out.string(), "--width", "16", "--height", "16",
                                   "--spp", "8"};
  args.insert(args.end(), extra.begin(), extra.end());
  return runWavepath(args);
}

// A Lambertian box of albedo 0.5 seen from outside: the default rule lights it with a white
// sky and says so; --sky none leaves it black and the note on the black image names the flag
// that brings light; --sky-color lights it with that colour (a convex Lambertian surface
// under a uniform sky has radiance albedo times the sky, exactly and without noise when BSDF
// sampling alone finds the sky).
TEST(DefaultLighting, TheRuleTheNotesAndTheSkyFlags) {
  const std::filesystem::path dir = scratchDirectory("default-lighting");
  TestScene scene;
  TestMaterial grey;
  grey.baseColor = glm::vec3(0.5f);
  scene.materials = {grey};
  scene.meshes = {box({-1, -1, -1}, {1, 1, 1}, false, 0)};
  scene.camera.position = {0, 0, 4};
  const std::filesystem::path file = writeGltf(scene, dir / "box.gltf");

  RunResult white = render(file, dir / "white.exr");
  ASSERT_EQ(white.exitCode, 0) << white.err;
  EXPECT_NE(white.err.find("has no lamps or emitters: lighting it with a constant white sky"), std::string::npos)
      << white.err;
  EXPECT_EQ(white.err.find("almost all black"), std::string::npos) << white.err;

  RunResult none = render(file, dir / "none.png", {"--sky", "none"});
  ASSERT_EQ(none.exitCode, 0) << none.err;
  EXPECT_EQ(none.err.find("white sky"), std::string::npos) << none.err;
  EXPECT_NE(none.err.find("none.png is almost all black (100% of its pixels): it has no sky"), std::string::npos)
      << none.err;
  EXPECT_NE(none.err.find("--sky-color 1,1,1"), std::string::npos) << none.err;

  RunResult coloured = render(file, dir / "coloured.exr", {"--sky-color", "0.2,0.4,0.6", "--mode", "bsdf"});
  ASSERT_EQ(coloured.exitCode, 0) << coloured.err;
  EXPECT_EQ(coloured.err.find("sky"), std::string::npos) << coloured.err;
  const RadianceImage image = readExr(dir / "coloured.exr");
  const glm::vec3 centre = image.mean[8 * 16 + 8];
  EXPECT_NEAR(centre.r, 0.1f, 1e-5f);
  EXPECT_NEAR(centre.g, 0.2f, 1e-5f);
  EXPECT_NEAR(centre.b, 0.3f, 1e-5f);

  RunResult both = render(file, dir / "both.exr", {"--sky", "none", "--sky-color", "1,1,1"});
  EXPECT_EQ(both.exitCode, 2) << both.err;
  RunResult nan = render(file, dir / "nan.exr", {"--sky-color", "nan,1,1"});
  EXPECT_EQ(nan.exitCode, 2) << nan.err;
}

// A closed room (a box whose faces look inwards) with a ceiling lamp brighter than the sky and
// no camera: the sky goes, the room encloses its centre, so the camera stands inside and sees
// the lit room, and says so. Lit by a sky instead, it is framed from outside, as is a closed
// object whose centre its own surface encloses.
TEST(AutomaticCamera, LooksFromInsideARoomLitFromWithin) {
  const std::filesystem::path dir = scratchDirectory("automatic-camera");
  TestScene scene;
  TestMaterial wall;
  wall.baseColor = glm::vec3(0.7f);
  TestMaterial lamp;
  lamp.baseColor = glm::vec3(0.0f);
  lamp.emission = glm::vec3(8.0f);
  scene.materials = {wall, lamp};
  scene.meshes = {box({-3, 0, -4}, {3, 2.5f, 4}, true, 0), ceilingLamp(2.5f, 1)};
  scene.withCamera = false;
  const std::filesystem::path file = writeGltf(scene, dir / "room.gltf");

  RunResult inside = render(file, dir / "inside.exr");
  ASSERT_EQ(inside.exitCode, 0) << inside.err;
  EXPECT_NE(inside.err.find("is lit by its emitters brighter than a white sky"), std::string::npos) << inside.err;
  EXPECT_NE(inside.err.find("has no camera, and its centre is enclosed and lit from within (a room?): looking from "
                            "inside"),
            std::string::npos)
      << inside.err;
  EXPECT_EQ(inside.err.find("almost all black"), std::string::npos) << inside.err;
  const RadianceImage image = readExr(dir / "inside.exr");
  const size_t lit = size_t(std::count_if(image.mean.begin(), image.mean.end(), [](glm::vec3 p) { return p.g > 0.0f; }));
  EXPECT_EQ(lit, image.mean.size());  // every pixel sees a lit wall, floor or ceiling

  RunResult outside = render(file, dir / "outside.exr", {"--sky-color", "1,1,1"});
  ASSERT_EQ(outside.exitCode, 0) << outside.err;
  EXPECT_NE(outside.err.find("has no camera: looking at the whole scene from +z"), std::string::npos) << outside.err;

  // A closed box lit by a bright lamp outside it: its centre is enclosed but sees no light.
  TestScene object = scene;
  object.meshes = {box({-1, -1, -1}, {1, 1, 1}, false, 0), ceilingLamp(3.0f, 1)};
  RunResult solid = render(writeGltf(object, dir / "object.gltf"), dir / "object.exr");
  ASSERT_EQ(solid.exitCode, 0) << solid.err;
  EXPECT_NE(solid.err.find("has no camera: looking at the whole scene from +z (the front of a glTF asset)"),
            std::string::npos)
      << solid.err;
}

// A --camera or --scene the file does not have is one error line, exit 1, and no image.
TEST(SceneFlags, NamingWhatTheFileLacksIsOneErrorLine) {
  const std::filesystem::path dir = scratchDirectory("scene-flags");
  TestScene scene;
  scene.materials = {TestMaterial{}};
  scene.meshes = {box({-1, -1, -1}, {1, 1, 1}, false, 0)};
  scene.camera.position = {0, 0, 4};
  const std::filesystem::path file = writeGltf(scene, dir / "box.gltf");
  for (const auto& [flag, value, phrase] :
       {std::tuple<std::string, std::string, std::string>{"--camera", "Missing", "--camera Missing names no camera"},
        {"--scene", "3", "--scene 3: scene 3 does not exist (the file has 1 scene)"}}) {
    RunResult r = render(file, dir / "out.png", {flag, value});
    EXPECT_EQ(r.exitCode, 1) << r.err;
    EXPECT_NE(r.err.find("wavepath: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find(phrase), std::string::npos) << r.err;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "out.png"));
  }
  RunResult byIndex = render(file, dir / "zero.exr", {"--camera", "0", "--scene", "0"});
  EXPECT_EQ(byIndex.exitCode, 0) << byIndex.err;
}

}  // namespace
}  // namespace wp::test
