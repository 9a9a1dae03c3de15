// `wavepath render`: loads a glTF scene, renders it headless and writes PNG or EXR.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <utility>

#include <CLI/CLI.hpp>

#include "app/backend_factory.h"
#include "app/interrupt.h"
#include "app/commands.h"
#include "app/number_checks.h"
#include "app/frame_parts.h"
#include "app/frame_sequence.h"
#include "app/pose_uploader.h"
#include "bvh/gpu_scene.h"
#include "core/error.h"
#include "core/log.h"
#include "image/image_io.h"
#include "render/render_identity.h"
#include "render/automatic_camera.h"
#include "render/wavefront.h"
#include "scene/gltf_loader.h"
#include "scene/scene_animation.h"

namespace wp {
namespace {

// Fills in the image size the user left out from the camera's aspect ratio.
void resolveImageSize(RenderOptions& options, const Scene& scene) {
  float aspect = scene.camera.aspectRatio;
  RenderSettings& s = options.settings;
  if (aspect <= 0.0f || (options.widthGiven && options.heightGiven)) {
    return;
  }
  if (options.heightGiven) {
    s.width = std::max(1u, uint32_t(std::lround(s.height * aspect)));
  } else {
    s.height = std::max(1u, uint32_t(std::lround(s.width / aspect)));
  }
}

// Seconds a render spends outside its passes, for --timings: on a big scene the set-up is
// part of what a user waits for, and must stay small beside the tracing.
struct TimeOutsidePasses {
  double device = 0.0;  // the backend chosen and its device opened
  double load = 0.0;    // the glTF file (and sky) read and checked
  double pack = 0.0;    // BVHs built and the scene packed (a later frame's: updated)
  double upload = 0.0;  // the scene and the path buffers put on the device
  double write = 0.0;   // the image read back, finished and written
};

double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

void printTimings(const RenderStats& stats, const TimeOutsidePasses& outside, const GpuScene& gpuScene,
                  const SceneUpdateTimes* update) {
  std::printf("outside the passes (ms): device %.1f, scene load %.1f, BVH and packing %.1f, upload %.1f, "
              "image write %.1f\n",
              outside.device * 1e3, outside.load * 1e3, outside.pack * 1e3, outside.upload * 1e3, outside.write * 1e3);
  if (update) {
    std::printf("scene update: %.1f ms (refit %.1f ms of %u meshes, %u rebuilt in %.1f ms, triangles %.1f ms, "
                "top level %.1f ms, lights %.1f ms)\n",
                update->totalMs(), update->refitMs, update->refits, update->rebuilds, update->rebuildMs,
                update->trianglesMs, update->tlasMs, update->lightsMs);
  } else {
    const TraversalStackNeeds stacks = gpuScene.stackNeeds();
    std::printf("BVH: %zu triangles, built in %.1f ms, SAH cost %.2f, stacks of %u (top level) and %u entries\n",
                gpuScene.triangleCount, gpuScene.bvhBuildSeconds * 1e3, gpuScene.sahCost, stacks.topLevel,
                stacks.bottomLevel);
  }
  std::printf("GPU time per stage over %u passes (ms):", stats.passes);
  for (int k = 0; k < kKernelCount; ++k) {
    std::printf(" %s %.1f%s", kernelName(Kernel(k)), stats.kernelMs[k], k + 1 < kKernelCount ? "," : "\n");
  }
  std::printf("peak memory: %.0f MiB\n", peakMemoryMiB());
}

// The frames to render (one, frame 0, when no sequence is asked for); the flags themselves
// were checked when they were parsed.
FrameRange framesToRender(const RenderOptions& o) {
  if (o.frames.empty()) return {};
  const FrameRange range = parseFrameRange(o.frames);
  checkFramePattern(o.output, range);
  return range;
}

// A render that displays almost all black (at least this share of its pixels 0 in every 8-bit
// channel of its PNG) gets a note saying why that may be and which flags change it.
constexpr double kAlmostBlackShare = 0.95;

void noteIfAlmostBlack(const RadianceImage& image, const DisplaySettings& display, const Scene& scene,
                       const std::string& output) {
  const std::vector<uint32_t> pixels = displayPixels(image, display);
  size_t black = 0;
  for (uint32_t p : pixels) black += (p & 0xffffffu) == 0 ? 1 : 0;
  const double share = pixels.empty() ? 0.0 : double(black) / double(pixels.size());
  if (share < kAlmostBlackShare) return;
  const std::string why = scene.sky.width == 0
                              ? "it has no sky, and its own lights reach little of what the camera sees, or too dimly "
                                "for the exposure; try --sky-color 1,1,1 for light, or --auto-exposure"
                              : "little light reaches what the camera sees, or too dimly for the exposure; try "
                                "--auto-exposure or --ev100, or check the camera with --camera";
  note(output + " is almost all black (" + std::to_string(int(std::lround(100.0 * share))) + "% of its pixels): " +
       why);
}

// The automatic camera of a scene without one (automatic_camera.h), with its note.
Camera frameAutomatically(const RenderOptions& o, const Scene& scene, const GpuScene& gpuScene) {
  const AutomaticCamera automatic = chooseAutomaticCamera(scene, gpuScene, o.scene);
  note(automatic.note);
  return automatic.camera;
}

// Renders one pose of the scene on `backend` and writes it to `output`, with the summary
// line. Returns 0, or the exit code of a render a signal interrupted (nothing is written
// then but its checkpoint).
// A scene without a camera is framed once, from its first pose, in `automaticCamera`.
// `outside` holds the seconds spent opening the device and loading the scene for this frame
// (0 after the first); renderFrame adds its own.
int renderFrame(const RenderOptions& o, const BackendChoice& choice, Backend& backend, PoseUploader& uploader,
                Scene scene, const std::string& output, std::optional<Camera>& automaticCamera,
                TimeOutsidePasses outside) {
  auto wallStart = std::chrono::steady_clock::now();
  const GpuScene& gpuScene = uploader.gpuSceneOf(scene);
  outside.pack = secondsSince(wallStart);
  if (!scene.hasCamera) {
    if (!automaticCamera) automaticCamera = frameAutomatically(o, scene, gpuScene);
    scene.camera = *automaticCamera;
  }
  applyCameraFlags(o.camera, scene.camera, gpuScene);
  auto uploadStart = std::chrono::steady_clock::now();
  WavefrontRenderer renderer(backend, scene, gpuScene, o.settings);
  outside.upload = secondsSince(uploadStart);
  if (renderer.tileCount() > 1) {
    // What a tiled render cannot do, and what to do instead.
    auto refuse = [&](const std::string& why, const std::string& flag) {
      throw Error("the image does not fit " + backend.deviceName() + " at once and is rendered in " +
                  std::to_string(renderer.tileCount()) + " tiles, " + why + "; leave out " + flag +
                  ", or render it in parts with --region and combine them with 'wavepath merge'");
    };
    if (o.timeLimitSeconds > 0.0) refuse("one after another, which a time limit would leave unfinished", "--time-limit");
    if (!o.checkpoint.path.empty()) refuse("which cannot be checkpointed", "--checkpoint");
    note("the " + std::to_string(o.settings.width) + "x" + std::to_string(o.settings.height) + " image is rendered in " +
         std::to_string(renderer.tileCount()) + " tiles, one after another: its accumulation does not fit " +
         backend.deviceName() + " at once");
  }
  Checkpoint here;
  here.identity = renderIdentity(gpuScene, makeRenderParams(scene, gpuScene, o.settings), o.settings);
  here.samplesPerPixel = o.settings.samplesPerPixel;
  here.firstSample = o.settings.firstSample;
  here.endSample = o.settings.sampleEnd();
  here.region = o.settings.pixelRegion();
  here.device = o.backend + ": " + backend.deviceName();
  RenderOutcome outcome = renderResumably(renderer, here, o.checkpoint, o.timeLimitSeconds);
  const RenderStats& stats = outcome.stats;
  if (outcome.interruptedBy != 0) {
    checkValidation(choice);
    if (o.checkpoint.path.empty())
      std::fprintf(stderr, "wavepath: %s: render stopped, nothing written (render with --checkpoint FILE to be able "
                           "to stop and resume)\n", signalName(outcome.interruptedBy));
    return o.checkpoint.path.empty() ? exitCodeInterrupted(outcome.interruptedBy) : kExitInterruptedResumable;
  }
  // What the image holds: a time limit may have ended it before --spp.
  RenderSettings rendered = o.settings;
  if (renderer.samplesPerPixelDone() < o.settings.samplesInRange()) {
    rendered.samplesPerPixel = renderer.samplesPerPixelDone();
    char text[96];
    std::snprintf(text, sizeof(text), "the time limit (%g s) ended the render at %u spp", o.timeLimitSeconds,
                  rendered.samplesPerPixel);
    note(text);
  }
  auto writeStart = std::chrono::steady_clock::now();
  RadianceImage image = renderer.image();
  checkValidation(choice);
  if (!image.sampleCount.empty()) {
    double samples = 0.0;
    for (float n : image.sampleCount) samples += n;
    char text[160];
    std::snprintf(text, sizeof(text), "adaptive sampling: %.1f samples per pixel on average, of at most %u (%.0f%%)",
                  samples / double(image.sampleCount.size()), rendered.samplesInRange(),
                  100.0 * samples / double(image.sampleCount.size()) / rendered.samplesInRange());
    note(text);
  }
  const DisplaySettings display = displaySettings(o.camera, scene.camera.optics, image);
  image.record = renderRecord(rendered, here.identity, display, o.camera.autoExposure);
  keepSelectedPasses(image, o.passes);
  writeImage(output, image, display);
  outside.write = secondsSince(writeStart);
  noteIfAlmostBlack(image, display, scene, output);
  if (!o.checkpoint.path.empty()) std::filesystem::remove(o.checkpoint.path);

  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  double rays = double(stats.extensionRays + stats.shadowRays);
  std::printf("%s: %s%ux%u, %u spp in %.2f s (%.2f s wall): %.3f M samples/s, %.2f Mrays/s "
              "(%.3f M extension + %.3f M shadow rays) on %s\n",
              output.c_str(), partText(o.settings).c_str(), o.settings.width, o.settings.height,
              rendered.samplesPerPixel, stats.seconds, wall, double(stats.samples) / stats.seconds * 1e-6,
              rays / stats.seconds * 1e-6, double(stats.extensionRays) * 1e-6, double(stats.shadowRays) * 1e-6,
              backend.deviceName().c_str());
  if (o.timings) {
    printTimings(stats, outside, gpuScene, uploader.lastUpdate());
  }
  return 0;
}

// A CLI11 check that `parse` accepts the text; its wp::Error's message says why not.
CLI::Validator parsedBy(void (*parse)(const std::string&), const char* name) {
  return CLI::Validator(
      [parse](std::string& text) -> std::string {
        try {
          parse(text);
        } catch (const Error& e) {
          return e.what();
        }
        return "";
      },
      name);
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a glTF scene to a PNG (sRGB) or EXR (linear radiance) file");
  cmd->add_option("-o,--output", o.output, "Output image: .png (tone-clamped sRGB) or .exr (linear, with variance)");
  cmd->add_flag("--timings", o.timings,
                "Print GPU time per stage, the time outside the passes (device, scene load, BVH and packing, upload, "
                "image write), peak memory, BVH and scene-update figures");
  addSceneFlags(*cmd, o);
  cmd->add_option("--frames", o.frames,
                  "Render frames A..B (inclusive) of the animations, frame n at n/fps seconds, to the -o pattern, "
                  "whose run of '#' becomes the zero-padded frame number (e.g. -o out_####.png)")
      ->check(parsedBy([](const std::string& text) { parseFrameRange(text); }, "A..B"))
      ->excludes(cmd->get_option("--time"));
  cmd->add_option("--fps", o.fps, "Frames per second of --frames (default 24)")->check(moreThanZero());
  cmd->add_option("--samples", o.samples,
                  "Render only samples A..B (inclusive, numbered from 0) of --spp: a batch of a frame split over "
                  "machines, to combine with 'wavepath merge'")
      ->check(parsedBy([](const std::string& text) { parseFrameRange(text, "--samples 0..15"); }, "A..B"));
  cmd->add_option("--region", o.region,
                  "Render only columns X0..X1-1 and rows Y0..Y1-1 of the image (X1, Y1 exclusive), to combine with "
                  "'wavepath merge'")
      ->check(parsedBy([](const std::string& text) { parseRegion(text); }, "X0,Y0,X1,Y1"));
  CLI::Option* checkpoint =
      cmd->add_option("--checkpoint", o.checkpoint.path,
                      "Save the render's progress to FILE every --checkpoint-every seconds and when SIGINT or "
                      "SIGTERM stops it (exit code 75); removed once the image is written")
          ->excludes(cmd->get_option("--frames"));
  cmd->add_option("--checkpoint-every", o.checkpoint.everySeconds,
                  "Seconds of rendering between checkpoints (default 60; 0: after every pass)")
      ->check(CLI::Validator(
          [](std::string& text) -> std::string {
            double value = 0.0;
            if (!CLI::detail::lexical_cast(text, value) || !std::isfinite(value) || value < 0.0)
              return "'" + text + "' is not a number of seconds (0 or more)";
            return "";
          },
          "SECONDS"))
      ->needs(checkpoint);
  CLI::Option* adaptive =
      cmd->add_option("--adaptive", o.settings.adaptiveThreshold,
                      "Adaptive sampling: from --adaptive-min-samples on, a pixel whose estimated relative error is "
                      "below THRESHOLD (e.g. 0.01) receives no more samples; --spp is the most a pixel gets")
          ->check(CLI::Range(1e-6f, 1.0f));
  cmd->add_option("--adaptive-min-samples", o.settings.adaptiveMinSamples,
                  "Samples every pixel gets before adaptive sampling may stop it (default 16)")
      ->check(CLI::Range(2u, kMaxSamplesPerPixel))
      ->needs(adaptive);
  cmd->add_option_function<std::string>(
         "--passes",
         [&o](const std::string& text) {
           if (text == "list") {
             std::fputs(passListText().c_str(), stdout);
             throw CLI::Success();
           }
           o.passes = parsePasses(text);
         },
         "Feature passes the EXR holds besides the radiance, for denoisers: a comma-separated list of albedo, "
         "normal, depth, or all (the default), none; 'list' prints what each holds")
      ->check(parsedBy([](const std::string& text) { if (text != "list") parsePasses(text); }, "LIST"));
  cmd->add_flag("--resume", o.checkpoint.resume,
                "Go on from the --checkpoint FILE of an interrupted render (same scene and flags)")
      ->needs(checkpoint);
  // A part of a split frame must hold the samples it was given, and a resumed render's time
  // before its checkpoint is not known: no time limit for either.
  cmd->add_option("--time-limit", o.timeLimitSeconds,
                  "Stop rendering (each frame) after SECONDS, once every pixel has finished the sample it is in, so "
                  "all have as many; --spp is then the most a pixel gets (without --spp: no limit but the time)")
      ->check(moreThanZero())
      ->excludes(cmd->get_option("--samples"))
      ->excludes(checkpoint);
  cmd->final_callback([&o, cmd] {
    if (o.timeLimitSeconds > 0.0 && cmd->get_option("--spp")->count() == 0)
      o.settings.samplesPerPixel = kMaxSamplesPerPixel;
  });
  return cmd;
}

void addSceneFlags(CLI::App& command, RenderOptions& o) {
  CLI::App* cmd = &command;
  RenderSettings& s = o.settings;
  cmd->add_option("scene", o.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
  cmd->add_option("--spp", s.samplesPerPixel, "Samples per pixel")->check(CLI::Range(1u, kMaxSamplesPerPixel));
  cmd->add_option_function<uint32_t>("--width", [&](const uint32_t& w) { s.width = w; o.widthGiven = true; },
                                     "Image width in pixels (default 512)")
      ->check(CLI::Range(1u, 16384u));
  cmd->add_option_function<uint32_t>("--height", [&](const uint32_t& h) { s.height = h; o.heightGiven = true; },
                                     "Image height in pixels (default from the camera's aspect ratio, else 512)")
      ->check(CLI::Range(1u, 16384u));
  cmd->add_option("--max-depth", s.maxBounces, "Maximum bounces, as Cycles counts them (0 = direct light only)")
      ->check(CLI::Range(0u, 1024u));
  cmd->add_option("--seed", s.seed, "Random seed; the same seed gives the same image");
  static const std::map<std::string, SamplerKind> samplers = {{"sobol", SamplerKind::Sobol},
                                                              {"independent", SamplerKind::Independent}};
  cmd->add_option("--sampler", s.sampler,
                  "Random numbers of the paths: sobol (Owen-scrambled Sobol, stratified across each pixel's samples; "
                  "the default) or independent (a PCG stream per path)")
      ->transform(CLI::CheckedTransformer(samplers, CLI::ignore_case));
  static const std::map<std::string, IntegratorMode> modes = {
      {"mis", IntegratorMode::Mis}, {"nee", IntegratorMode::NeeOnly}, {"bsdf", IntegratorMode::BsdfOnly}};
  cmd->add_option("--mode", s.mode,
                  "Light sampling: mis (light and BSDF sampling, balance heuristic), nee (light sampling only), "
                  "bsdf (BSDF sampling only)")
      ->transform(CLI::CheckedTransformer(modes, CLI::ignore_case));
  // Shading switches (materials), off by default.
  cmd->add_flag("--widen-roughness", s.widenRoughness,
                "Sample rough glass from Walter et al.'s widened Beckmann lobe (pdfs follow: still unbiased)");
  cmd->add_flag("--fixed-lobe-choice", s.fixedLobeChoice,
                "For comparisons: plastic picks specular or diffuse 50/50 instead of by Fresnel (still unbiased)");
  cmd->add_option("--clamp", s.contributionClamp,
                  "Biased: clamp the luminance of each contribution but emission seen by the camera (0 = off)")
      ->check(zeroOrMore());
  cmd->add_option("--filter-glossy", s.filterGlossy,
                  "Biased, as Cycles' Filter Glossy (Cycles' default 1): roughen glossy surfaces that a path reaches "
                  "after unlikely bounces, for fewer fireflies (0 = off)")
      ->check(zeroOrMore());
  static const std::map<std::string, LightSelection> selections = {{"power", LightSelection::Power},
                                                                   {"solid-angle", LightSelection::SolidAngle}};
  cmd->add_option("--light-selection", s.lightSelection,
                  "How light sampling picks a light: power (alias table, the default) or solid-angle (subtended "
                  "solid angle times luminance from the shading point; a pass over all lights per sample)")
      ->transform(CLI::CheckedTransformer(selections, CLI::ignore_case));
  cmd->add_option("--rr-start", s.russianRouletteStart, "First bounce at which Russian roulette may end a path");
  cmd->add_option("--max-paths", s.maxPaths,
                  "Paths in flight per pass (bounds GPU memory, ~200 bytes each; capped at what the device holds). "
                  "Default: 4194240 on a GPU, 1048576 on a CPU (lavapipe, PoCL)")
      ->check(CLI::Range(64u, 4194240u));
  cmd->add_option("--backend", o.backend,
                  "Compute backend: vulkan, opencl, or auto (the default, or WAVEPATH_BACKEND's): Vulkan on a GPU, "
                  "else OpenCL where it has a device (PoCL on a CPU: faster there than lavapipe), else Vulkan; "
                  "'wavepath devices' says which")
      ->check(CLI::IsMember({"auto", "vulkan", "opencl"}));
  cmd->add_option("--device", o.device,
                  "Device index in the backend's list from 'wavepath devices' (default: the most capable)")
      ->check(zeroOrMore());
  cmd->add_option("--cl-dispatch", o.clDispatch,
                  "OpenCL only: launch extend, shade and connect at the queue lengths read back each bounce "
                  "(readback, the default, faster on PoCL) or at every path of the pass, the work items past the "
                  "queue exiting at once (max)")
      ->check(CLI::IsMember({"readback", "max"}));
  cmd->add_flag("--validate", o.validate,
                "Vulkan: run with the Khronos validation layer (with synchronization validation); OpenCL: build the "
                "kernels with warnings as errors and check the queue counters; fail on any error");
  addCameraFlags(*cmd, o.camera);
  cmd->add_option("--time", o.time, "Pose the scene's animations at this time, in seconds (default: the rest pose)");
  cmd->add_option("--camera", o.cameraName,
                  "The file camera to look through: its index, or the name of the camera or of its node (default: "
                  "the first camera of the scene)");
  cmd->add_option("--scene", o.sceneIndex, "The glTF scene to render, by index (default: the file's default scene)");
  cmd->add_option("--variant", o.variant,
                  "The KHR_materials_variants variant to show, by name (default: the file's default materials)");
  cmd->add_option("--sky", o.sky,
                  "Equirectangular HDR sky (.hdr or .exr) lighting the scene from afar, or 'none' for no sky "
                  "(default: a white sky unless the scene has lamps or emitters brighter than it)");
  cmd->add_option_function<std::vector<float>>(
         "--sky-color", [&o](const std::vector<float>& rgb) { o.skyColor = glm::vec3(rgb[0], rgb[1], rgb[2]); },
         "A constant sky of this linear RGB radiance, e.g. 0.05,0.05,0.05")
      ->delimiter(',')
      ->expected(3)
      ->check(CLI::Range(0.0f, 1e9f))
      ->excludes("--sky");
  cmd->add_option("--sky-intensity", o.skyIntensity, "Multiplier of the sky's radiance")->check(CLI::Range(0.0f, 1e9f));
  cmd->add_option("--sky-rotation", o.skyRotationDegrees, "Rotation of the sky about +y, in degrees");
  static const std::map<std::string, bool> onOff = {{"on", true}, {"off", false}};
  cmd->add_option("--sky-sampling", s.skySampling,
                  "on: next event estimation samples the sky by luminance (default); off: only BSDF rays find it")
      ->transform(CLI::CheckedTransformer(onOff, CLI::ignore_case));
}

double shutterSeconds(const RenderOptions& o, const Scene& scene) {
  return o.camera.shutter.value_or(scene.camera.optics.shutter);
}

bool validationRequested(const RenderOptions& o) {
  const char* validationEnv = std::getenv("WAVEPATH_VALIDATION");
  return o.validate || (validationEnv != nullptr && std::string(validationEnv) == "1");
}

Scene loadSceneWithSky(RenderOptions& o) {
  LoadOptions load;
  load.defaultSky = o.sky.empty() && !o.skyColor;
  load.scene = o.sceneIndex;
  load.camera = o.cameraName;
  load.variant = o.variant;
  Scene scene = loadScene(o.scene, load);
  if (o.skyColor) {
    scene.sky = makeEnvironmentMap(1, 1, {*o.skyColor});
  } else if (!o.sky.empty() && o.sky != "none") {
    scene.sky = loadEnvironmentMap(o.sky);
  }
  checkSkyIntensity(scene.sky, o.skyIntensity);
  scene.skyIntensity = o.skyIntensity;
  scene.skyRotation = glm::radians(o.skyRotationDegrees);
  resolveImageSize(o, scene);
  return scene;
}

PreparedScene prepareScene(RenderOptions& o) {
  PreparedScene p;
  Scene loaded = loadSceneWithSky(o);
  p.scene = o.time ? poseSceneOverShutter(loaded, *o.time, shutterSeconds(o, loaded)) : loaded;
  const GpuScene& gpuScene = p.uploader.gpuSceneOf(p.scene);
  if (!p.scene.hasCamera) p.scene.camera = loaded.camera = frameAutomatically(o, p.scene, gpuScene);
  applyCameraFlags(o.camera, p.scene.camera, gpuScene);
  // Kept only to pose again: a static scene needs no second copy of its meshes.
  if (loaded.animation) p.loaded = std::move(loaded);
  return p;
}

int runRender(RenderOptions o) {
  bool validate = validationRequested(o);
  if (o.output.empty()) {
    o.output = std::filesystem::path(o.scene).stem().string() + (o.frames.empty() ? ".png" : "_####.png");
  }
  const FrameRange frames = framesToRender(o);
  checkOutputPath(framePath(o.output, frames.first));
  o.settings.featurePasses = outputKeepsFeaturePasses(o.output, o.passes);
  checkCheckpointFlags(o.checkpoint, o.output);
  catchInterrupts();

  // The device first: a missing or unusable one is one error line before any scene work.
  TimeOutsidePasses outside;
  auto start = std::chrono::steady_clock::now();
  o.backend = chooseBackendName(o.backend);
  BackendChoice choice{o.backend, o.device, validate, o.clDispatch};
  std::unique_ptr<Backend> backend = createBackend(choice);
  outside.device = secondsSince(start);
  start = std::chrono::steady_clock::now();
  const Scene scene = loadSceneWithSky(o);
  outside.load = secondsSince(start);
  applyPartFlags(o.settings, o.samples, o.region);
  if (!o.frames.empty() && !scene.animation) {
    note(o.scene + " has no animation: every frame is the same image");
  } else if (!o.frames.empty() && frames.last / o.fps > scene.animation->duration) {
    char duration[32];
    std::snprintf(duration, sizeof(duration), "%g", scene.animation->duration);
    note(o.scene + "'s animations end at " + duration + " s: later frames hold their last pose");
  }
  PoseUploader uploader;
  const double shutter = shutterSeconds(o, scene);
  std::optional<Camera> automaticCamera;
  for (uint32_t frame = frames.first;; ++frame) {
    const std::optional<double> time = o.frames.empty() ? o.time : std::optional<double>(frame / o.fps);
    const int code = renderFrame(o, choice, *backend, uploader, time ? poseSceneOverShutter(scene, *time, shutter) : scene,
                                 framePath(o.output, frame), automaticCamera, outside);
    if (code != 0) return code;
    outside = {};  // the device and the scene serve every frame
    if (frame == frames.last) break;  // tested here, as frames.last may be the largest uint32_t
  }
  return 0;
}

}  // namespace wp
