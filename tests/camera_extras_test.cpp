// Physical camera settings from a glTF camera's extras.wavepath.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.h"
#include "scene/gltf_loader.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

// One triangle and a camera whose extras are `cameraExtras`.
std::filesystem::path writeScene(const std::string& cameraExtras) {
  std::filesystem::path file = scratchDirectory("camera-extras") / "scene.gltf";
  std::ofstream(file) << R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1]}],
    "nodes": [{"mesh": 0}, {"camera": 0, "translation": [0, 0, 3]}],
    "cameras": [{"type": "perspective", "perspective": {"yfov": 0.7, "znear": 0.01}, "extras": )"
                      << cameraExtras << R"(}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}}]}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAA"}]})";
  return file;
}

TEST(CameraExtras, AreReadInTheirUnits) {
  Scene scene = loadScene(writeScene(R"({"wavepath": {"fStop": 2.8, "focusDistance": 1.5, "focalLength": 50,
      "blades": 6, "bladeRotation": 0.1, "sensorWidth": 24, "sensorHeight": 16, "shutter": 0.004, "iso": 400}})"));
  const CameraOptics& o = scene.camera.optics;
  EXPECT_FLOAT_EQ(o.fNumber, 2.8f);
  EXPECT_FLOAT_EQ(o.focusDistance, 1.5f);
  EXPECT_FLOAT_EQ(o.focalLength, 0.05f);  // millimetres in the file, metres inside
  EXPECT_EQ(o.blades, 6u);
  EXPECT_FLOAT_EQ(o.bladeRotation, 0.1f);
  EXPECT_FLOAT_EQ(o.sensorSize.x, 0.024f);
  EXPECT_FLOAT_EQ(o.sensorSize.y, 0.016f);
  EXPECT_FLOAT_EQ(o.shutter, 0.004f);
  EXPECT_FLOAT_EQ(o.iso, 400.0f);
}

TEST(CameraExtras, AbsentMeansAPinholeOnAFullFrameSensor) {
  Scene scene = loadScene(writeScene("{}"));
  EXPECT_EQ(scene.camera.optics.fNumber, 0.0f);
  EXPECT_FLOAT_EQ(scene.camera.optics.sensorSize.x, 0.036f);
}

TEST(CameraExtras, BadValuesAreOneClearError) {
  try {
    loadScene(writeScene(R"({"wavepath": {"fStop": -2}})"));
    FAIL() << "a negative f-stop was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("fStop"), std::string::npos) << e.what();
  }
}

TEST(CameraExtras, FocusInsideTheLensIsRejectedByTheCommandLine) {
  std::filesystem::path scene = writeScene("{}");
  RunResult r = runWavepath({"render", scene.string(), "-o", (scene.parent_path() / "x.png").string(), "--fstop",
                             "2", "--focal-length", "50", "--focus-distance", "0.01", "--width", "8", "--height",
                             "8", "--spp", "1"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("focus distance"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace wp::test
