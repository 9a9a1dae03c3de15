// libFuzzer target: any bytes as a wavepath command line (arguments separated by NUL bytes),
// parsed as main() parses it; a parse that succeeds must leave every number finite and give
// a finite, positive exposure and sane frame names.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "app/camera_options.h"
#include "app/command_line.h"
#include "app/frame_sequence.h"
#include "bvh/gpu_scene.h"
#include "core/error.h"

namespace {

[[noreturn]] void finding(const std::string& what) {
  std::fprintf(stderr, "fuzz finding: %s\n", what.c_str());
  std::abort();
}

void checkNumber(double value, const char* flag) {
  if (!std::isfinite(value)) finding(std::string(flag) + " parsed to a number that is not finite");
}

template <typename T>
void checkNumber(const std::optional<T>& value, const char* flag) {
  if (value) checkNumber(double(*value), flag);
}

// A one-triangle scene in front of the camera, for autofocus.
const wp::GpuScene& triangleScene() {
  static const wp::GpuScene scene = [] {
    wp::Scene s;
    wp::Mesh mesh;
    mesh.positions = {{-1, -1, -2}, {1, -1, -2}, {0, 1, -2}};
    mesh.indices = {0, 1, 2};
    mesh.materials = {0};
    s.meshes.push_back(mesh);
    s.instances.push_back({0, glm::mat4(1.0f), false, std::nullopt});
    s.materials.emplace_back();
    return wp::packScene(s);
  }();
  return scene;
}

void checkRenderOptions(const wp::RenderOptions& o) {
  checkNumber(o.settings.contributionClamp, "--clamp");
  checkNumber(o.skyIntensity, "--sky-intensity");
  checkNumber(o.skyRotationDegrees, "--sky-rotation");
  checkNumber(o.time, "--time");
  checkNumber(o.fps, "--fps");
  checkNumber(o.checkpoint.everySeconds, "--checkpoint-every");
  if (o.skyColor) {
    for (int c = 0; c < 3; ++c) checkNumber((*o.skyColor)[c], "--sky-color");
  }
  const wp::CameraFlags& f = o.camera;
  checkNumber(f.fStop, "--fstop");
  checkNumber(f.focusDistance, "--focus-distance");
  checkNumber(f.focalLengthMm, "--focal-length");
  checkNumber(f.shutter, "--shutter");
  checkNumber(f.iso, "--iso");
  checkNumber(f.ev100, "--ev100");
  checkNumber(f.gamma, "--gamma");
  try {
    wp::Camera camera;
    wp::applyCameraFlags(f, camera, triangleScene());
    wp::RadianceImage grey{1, 1, {glm::vec3(0.18f)}, {}};
    const wp::DisplaySettings d = wp::displaySettings(f, camera.optics, grey);
    if (!(std::isfinite(d.exposure) && d.exposure > 0.0f)) finding("the flags give exposure " + std::to_string(d.exposure));
    if (!(std::isfinite(d.gamma) && d.gamma > 0.0f)) finding("the flags give gamma " + std::to_string(d.gamma));
    if (!o.frames.empty()) {
      const wp::FrameRange range = wp::parseFrameRange(o.frames);
      wp::checkFramePattern(o.output, range);
      wp::framePath(o.output, range.last);
    }
  } catch (const wp::Error&) {
    // Flags that contradict each other (a focus inside the lens): one line, as main() says it.
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args = {"wavepath"};
  std::string arg;
  for (size_t i = 0; i < size && args.size() < 64; ++i) {
    if (data[i] == 0) {
      args.push_back(arg);
      arg.clear();
    } else {
      arg += char(data[i]);
    }
  }
  if (!arg.empty()) args.push_back(arg);
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());

  wp::CommandLine line;
  if (wp::parseCommandLine(line, int(argv.size()), argv.data())) return 0;
  if (line.render->parsed()) checkRenderOptions(line.renderOptions);
  if (line.view->parsed()) {
    checkRenderOptions(line.viewOptions.render);
    checkNumber(line.viewOptions.frameBudgetMs, "--frame-budget");
  }
  return 0;
}
