// The wavefront integrator's orchestration: the order of the stages within a sample pass,
// and the passes that make a render. Written once above the Backend interface.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "image/image_io.h"
#include "render/backend.h"
#include "render/settings.h"

namespace wp {

struct Scene;
struct GpuScene;

struct RenderStats {
  double seconds = 0.0;
  uint64_t samples = 0;  // camera paths traced
  uint64_t extensionRays = 0;
  uint64_t shadowRays = 0;
  uint32_t passes = 0;
  std::array<double, kKernelCount> kernelMs{};  // summed over passes
};

// The GPU-side parameters of a render of `scene` (camera, image, integrator switches), with
// the whole image as its tile.
gpu::RenderParams makeRenderParams(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings);

// A rectangle of the image rendered on its own (RenderParams::tile).
struct Tile {
  uint32_t x = 0, y = 0, width = 0, height = 0;
};

// The image cut into bands of whole rows, as few as keep each under `maxPixels` and as even
// as that allows; a single row when not even one fits (the backend then says so).
std::vector<Tile> splitIntoTiles(uint32_t width, uint32_t height, uint64_t maxPixels);

class WavefrontRenderer {
public:
  // Loads the scene into `backend` and configures it for `settings`, with the paths in
  // flight lowered to what the device can hold, and the image cut into tiles when its
  // accumulation does not fit the device at once.
  WavefrontRenderer(Backend& backend, const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings);

  // Traces samplesPerPixel samples of every pixel, calling progress(fraction) after each
  // pass; tile after tile when there are several, each pixel's samples as without tiles, so
  // the image is the same bit for bit. Accumulates onto earlier calls' samples (with several
  // tiles, each call renders the image anew).
  RenderStats render(const std::function<void(double)>& progress);

  // Progressive rendering (the viewer): runs whole passes, continuing where the last one
  // stopped, until `budgetSeconds` is spent (at least one pass) or every pixel has
  // `samplesPerPixel` samples. Passes are sized from the time earlier passes took per path
  // so they end near the budget (at most the paths in flight). Paths follow the same order
  // as render()'s, so a progressive render that reaches N samples equals render() of N
  // samples bit for bit. Throws wp::Error when the image needs tiles.
  RenderStats renderFor(double budgetSeconds, uint32_t samplesPerPixel);
  // Replaces the settings and the scene's camera and sky (makeRenderParams) and clears the
  // accumulation. Reuploads the scene when `reloadScene` (a changed GpuScene).
  void restart(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings, bool reloadScene);
  // Samples every pixel has so far (some pixels may have one more, mid-pass).
  uint32_t samplesPerPixelDone() const;

  // Per-pixel mean radiance and the variance of that mean, from the samples so far. With
  // several tiles, the image render() put together, handed over once.
  RadianceImage image();
  // How many tiles the image is rendered in (1 when it fits the device at once).
  size_t tileCount() const { return tiles_.size(); }

private:
  void runPass(uint32_t firstPixel, uint32_t firstSample, uint32_t pathCount, RenderStats& stats);
  // Runs the next pass of at most `maxCount` paths, stopping at path index `end`.
  void runNextPass(uint64_t end, uint64_t maxCount, RenderStats& stats);
  void configure(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings);
  // Points the backend at tile `index` with an empty accumulation.
  void configureTile(size_t index);
  // The current tile's mean and variance from its accumulation.
  RadianceImage tileImage();

  Backend& backend_;
  RenderSettings settings_;
  gpu::RenderParams params_;
  std::vector<Tile> tiles_;
  size_t tile_ = 0;  // the one configured
  RadianceImage image_;  // with several tiles: the finished ones, put together
  // Paths traced in the current tile since it was configured, in render order: path k is
  // sample k / pixels of pixel k % pixels of the tile.
  uint64_t pathsDone_ = 0;
  // Measured seconds per path of the last progressive pass; 0 before the first.
  double secondsPerPath_ = 0.0;
};

}  // namespace wp
