// The wavepath subcommands and their options.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "app/camera_options.h"
#include "app/pose_uploader.h"
#include "app/resumable_render.h"
#include "bvh/gpu_scene.h"
#include "image/feature_passes.h"
#include "render/settings.h"
#include "scene/scene.h"

namespace CLI {
class App;
}

namespace wp {

struct RenderOptions {
  std::string scene;
  std::string output;  // empty: <scene name>.png in the working directory
  RenderSettings settings;
  CameraFlags camera;
  std::string cameraName;               // --camera N|NAME: the file camera to look through
  std::optional<size_t> sceneIndex;     // --scene N: the glTF scene to render
  std::string variant;                  // --variant NAME: a KHR_materials_variants variant
  std::string sky;                      // "none", or an .hdr or .exr sky; empty: the default rule
  std::optional<glm::vec3> skyColor;    // --sky-color R,G,B: a constant sky
  float skyIntensity = 1.0f;
  float skyRotationDegrees = 0.0f;
  bool widthGiven = false;
  bool heightGiven = false;
  std::string backend;  // --backend; empty: not given (chooseBackendName decides)
  int device = -1;
  std::string clDispatch = "readback";  // OpenCL only: how queue-sized launches are sized (ClDispatch)
  bool validate = false;  // validation (Vulkan: Khronos layer); also WAVEPATH_VALIDATION=1
  bool timings = false;   // per-stage GPU times, memory and BVH figures
  std::optional<double> time;  // --time: seconds at which the scene is posed; unset: its rest pose
  std::string frames;          // --frames A..B: an image sequence, frame n at n / fps seconds
  double fps = 24.0;
  std::string samples;  // --samples A..B: render only these samples of --spp (a batch of a split frame)
  std::string region;   // --region X0,Y0,X1,Y1: render only this crop
  CheckpointOptions checkpoint;
  // --time-limit: seconds of rendering after which each frame ends with the sample in
  // progress; 0: none.
  double timeLimitSeconds = 0.0;
  PassSelection passes;  // --passes: the feature passes an EXR holds
};

// Adds `render` to the app; the options are filled in when it parses.
CLI::App* addRenderCommand(CLI::App& app, RenderOptions& options);
// Renders as the options say; throws wp::Error on bad input. Returns the exit code.
int runRender(RenderOptions options);

// The scene argument and every flag `render` and `view` share (settings, backend, camera,
// sky), added to `command`.
void addSceneFlags(CLI::App& command, RenderOptions& options);
// --validate or WAVEPATH_VALIDATION=1.
bool validationRequested(const RenderOptions& options);

// A scene as the viewer starts from it, ready to be posed at other times.
struct PreparedScene {
  Scene loaded;           // as loaded (the rest pose), which every pose is made from; empty without animation
  Scene scene;            // posed at --time over the shutter interval, with the camera flags applied
  PoseUploader uploader;  // holds the GPU form of `scene`, and updates it to later poses
};
// Loads the scene and sky and fills in the image size the flags left out; throws wp::Error
// on bad input.
Scene loadSceneWithSky(RenderOptions& options);
// The camera's shutter time: --shutter, else the file's camera extras; 0 when neither says.
// With an animation, a render at a time sees the scene over this interval (motion blur).
double shutterSeconds(const RenderOptions& options, const Scene& scene);
// loadSceneWithSky, posed at --time when given (over the shutter interval) and uploaded as
// `render` does it, with the camera flags applied.
PreparedScene prepareScene(RenderOptions& options);

struct ViewOptions {
  RenderOptions render;
  bool sampleLimit = false;    // --spp given: stop accumulating there
  uint32_t frames = 0;         // scripted: run this many frames (and reach --spp), then exit
  std::string screenshot;      // scripted: write the image here at exit (.png display, .exr radiance)
  std::string windowCapture;   // scripted: write the whole window, panel included, as PNG at exit
  float frameBudgetMs = 33.0f;  // time per displayed frame (path tracing gets what the rest leaves)
  bool hidePanel = false;
  bool play = false;  // start playing the animation (at --time, else 0)
  bool loop = false;  // play the animation in a loop; else playback stops at its end
};

// Adds `view` to the app.
CLI::App* addViewCommand(CLI::App& app, ViewOptions& options);
// Opens the viewer window; throws wp::Error when it cannot. Returns the exit code.
int runView(ViewOptions options);

// `wavepath merge PARTS... -o OUT`: parts of a split frame combined into the frame.
struct MergeOptions {
  std::vector<std::string> parts;
  std::string output;
};
CLI::App* addMergeCommand(CLI::App& app, MergeOptions& options);
int runMerge(const MergeOptions& options);

CLI::App* addDevicesCommand(CLI::App& app);
int runDevices();

}  // namespace wp
