// The wavepath subcommands and their options.
#pragma once

#include <optional>
#include <string>

#include "app/camera_options.h"
#include "render/settings.h"

namespace CLI {
class App;
}

namespace wp {

struct RenderOptions {
  std::string scene;
  std::string output;  // empty: <scene name>.png in the working directory
  RenderSettings settings;
  CameraFlags camera;
  std::string sky;              // an .hdr or .exr sky replacing the scene's; empty: keep it
  float skyIntensity = 1.0f;
  float skyRotationDegrees = 0.0f;
  bool widthGiven = false;
  bool heightGiven = false;
  std::string backend = "vulkan";
  int device = -1;
  std::string clDispatch = "readback";  // OpenCL only: how queue-sized launches are sized (ClDispatch)
  bool validate = false;  // validation (Vulkan: Khronos layer); also WAVEPATH_VALIDATION=1
  bool timings = false;   // per-stage GPU times, memory and BVH figures
  std::optional<double> time;  // --time: seconds at which the scene is posed; unset: its rest pose
  std::string frames;          // --frames A..B: an image sequence, frame n at n / fps seconds
  double fps = 24.0;
};

// Adds `render` to the app; the options are filled in when it parses.
CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options);
// Renders as the options say; throws wp::Error on bad input. Returns the exit code.
int runRender(RenderOptions options);

CLI::App* addDevicesCommand(CLI::App& app);
int runDevices();

}  // namespace wp
