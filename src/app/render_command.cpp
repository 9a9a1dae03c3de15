// `wavepath render`: loads a glTF scene, renders it headless and writes PNG or EXR.
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <map>

#include <CLI/CLI.hpp>

#include "app/backend_factory.h"
#include "app/commands.h"
#include "app/progress_bar.h"
#include "bvh/gpu_scene.h"
#include "bvh/instance_baking.h"
#include "core/error.h"
#include "image/image_io.h"
#include "render/wavefront.h"
#include "scene/gltf_loader.h"

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

double peakMemoryMiB() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / 1024.0;
}

void printTimings(const RenderStats& stats, const GpuScene& gpuScene) {
  std::printf("BVH: %zu triangles, built in %.1f ms, SAH cost %.2f\n", gpuScene.triangleCount,
              gpuScene.bvhBuildSeconds * 1e3, gpuScene.sahCost);
  std::printf("GPU time per stage over %u passes (ms):", stats.passes);
  for (int k = 0; k < kKernelCount; ++k) {
    std::printf(" %s %.1f%s", kernelName(Kernel(k)), stats.kernelMs[k], k + 1 < kKernelCount ? "," : "\n");
  }
  std::printf("peak memory: %.0f MiB\n", peakMemoryMiB());
}

}  // namespace

CLI::App* addRenderCommand(CLI::App& app, RenderOptions& o) {
  CLI::App* cmd = app.add_subcommand("render", "Render a glTF scene to a PNG (sRGB) or EXR (linear radiance) file");
  cmd->add_option("-o,--output", o.output, "Output image: .png (tone-clamped sRGB) or .exr (linear, with variance)");
  cmd->add_flag("--timings", o.timings, "Print GPU time per stage, peak memory and BVH figures");
  addSceneFlags(*cmd, o);
  return cmd;
}

void addSceneFlags(CLI::App& command, RenderOptions& o) {
  CLI::App* cmd = &command;
  RenderSettings& s = o.settings;
  cmd->add_option("scene", o.scene, "glTF 2.0 scene (.gltf or .glb)")->required();
  cmd->add_option("--spp", s.samplesPerPixel, "Samples per pixel")->check(CLI::Range(1u, 1u << 20));
  cmd->add_option_function<uint32_t>("--width", [&](const uint32_t& w) { s.width = w; o.widthGiven = true; },
                                     "Image width in pixels (default 512)")
      ->check(CLI::Range(1u, 16384u));
  cmd->add_option_function<uint32_t>("--height", [&](const uint32_t& h) { s.height = h; o.heightGiven = true; },
                                     "Image height in pixels (default from the camera's aspect ratio, else 512)")
      ->check(CLI::Range(1u, 16384u));
  cmd->add_option("--max-depth", s.maxBounces, "Maximum bounces, as Cycles counts them (0 = direct light only)")
      ->check(CLI::Range(0u, 1024u));
  cmd->add_option("--seed", s.seed, "Random seed; the same seed gives the same image");
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
      ->check(CLI::NonNegativeNumber);
  static const std::map<std::string, LightSelection> selections = {{"power", LightSelection::Power},
                                                                   {"solid-angle", LightSelection::SolidAngle}};
  cmd->add_option("--light-selection", s.lightSelection,
                  "How light sampling picks a light: power (alias table, the default) or solid-angle (subtended "
                  "solid angle times luminance from the shading point; a pass over all lights per sample)")
      ->transform(CLI::CheckedTransformer(selections, CLI::ignore_case));
  cmd->add_option("--rr-start", s.russianRouletteStart, "First bounce at which Russian roulette may end a path");
  cmd->add_option("--max-paths", s.maxPaths, "Paths in flight per pass (bounds GPU memory, ~200 bytes each; capped at what the device holds)")
      ->check(CLI::Range(64u, 4194240u));
  cmd->add_option("--backend", o.backend, "Compute backend: vulkan (the default) or opencl")
      ->check(CLI::IsMember({"vulkan", "opencl"}));
  cmd->add_option("--device", o.device,
                  "Device index in the chosen backend's list from 'wavepath devices' (default: the most capable)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--cl-dispatch", o.clDispatch,
                  "OpenCL only: launch extend, shade and connect at the queue lengths read back each bounce "
                  "(readback, the default, faster on PoCL) or at every path of the pass, the work items past the "
                  "queue exiting at once (max)")
      ->check(CLI::IsMember({"readback", "max"}));
  cmd->add_flag("--validate", o.validate,
                "Vulkan: run with the Khronos validation layer (with synchronization validation); OpenCL: build the "
                "kernels with warnings as errors and check the queue counters; fail on any error");
  addCameraFlags(*cmd, o.camera);
  cmd->add_option("--sky", o.sky, "Equirectangular HDR sky (.hdr or .exr) lighting the scene from afar");
  cmd->add_option("--sky-intensity", o.skyIntensity, "Multiplier of the sky's radiance")->check(CLI::Range(0.0f, 1e9f));
  cmd->add_option("--sky-rotation", o.skyRotationDegrees, "Rotation of the sky about +y, in degrees");
  static const std::map<std::string, bool> onOff = {{"on", true}, {"off", false}};
  cmd->add_option("--sky-sampling", s.skySampling,
                  "on: next event estimation samples the sky by luminance (default); off: only BSDF rays find it")
      ->transform(CLI::CheckedTransformer(onOff, CLI::ignore_case));
}

bool validationRequested(const RenderOptions& o) {
  const char* validationEnv = std::getenv("WAVEPATH_VALIDATION");
  return o.validate || (validationEnv != nullptr && std::string(validationEnv) == "1");
}

PreparedScene prepareScene(RenderOptions& o) {
  PreparedScene p;
  p.scene = loadScene(o.scene, o.sky.empty());
  if (!o.sky.empty()) {
    p.scene.sky = loadEnvironmentMap(o.sky);
  }
  p.scene.skyIntensity = o.skyIntensity;
  p.scene.skyRotation = glm::radians(o.skyRotationDegrees);
  resolveImageSize(o, p.scene);
  p.gpuScene = packScene(bakeSingleUseMeshes(p.scene));
  applyCameraFlags(o.camera, p.scene.camera, p.gpuScene);
  return p;
}

int runRender(RenderOptions o) {
  auto wallStart = std::chrono::steady_clock::now();
  bool validate = validationRequested(o);
  if (o.output.empty()) {
    o.output = std::filesystem::path(o.scene).stem().string() + ".png";
  }
  checkOutputPath(o.output);

  auto [scene, gpuScene] = prepareScene(o);

  BackendChoice choice{o.backend, o.device, validate, o.clDispatch};
  std::unique_ptr<Backend> backend = createBackend(choice);
  WavefrontRenderer renderer(*backend, scene, gpuScene, o.settings);
  ProgressBar bar;
  RenderStats stats = renderer.render([&](double fraction) { bar.update(fraction); });
  bar.finish();
  RadianceImage image = renderer.image();
  checkValidation(choice);
  writeImage(o.output, image, displaySettings(o.camera, scene.camera.optics, image));

  double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wallStart).count();
  double rays = double(stats.extensionRays + stats.shadowRays);
  std::printf("%s: %ux%u, %u spp in %.2f s (%.2f s wall): %.3f M samples/s, %.2f Mrays/s "
              "(%.1f M extension + %.1f M shadow rays) on %s\n",
              o.output.c_str(), o.settings.width, o.settings.height, o.settings.samplesPerPixel, stats.seconds, wall,
              double(stats.samples) / stats.seconds * 1e-6, rays / stats.seconds * 1e-6,
              double(stats.extensionRays) * 1e-6, double(stats.shadowRays) * 1e-6, backend->deviceName().c_str());
  if (o.timings) {
    printTimings(stats, gpuScene);
  }
  return 0;
}

}  // namespace wp
