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

// The GPU-side parameters of a render of `scene` (camera, image, integrator switches).
gpu::RenderParams makeRenderParams(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings);

// Paths in flight per pass where the settings leave it to the device (RenderSettings::maxPaths
// 0). A GPU keeps its cores busy through a pass's last bounces, when the queues have shrunk,
// only with many more paths than it runs at once: as many as one dispatch addresses on every
// Vulkan device (65535 workgroups of 64; NVIDIA H200, Cornell box 1280x720 at 512 spp: 2^20
// paths 0.61 s, these 0.39 s). A CPU runs a few lanes at a time and gains nothing from more
// than 2^20 (lavapipe, the box 512x512 at 64 spp: 21.6 s against 24.0 s with these).
uint32_t defaultPathsInFlight(bool onCpu);

// `region` cut into bands of whole rows, as few as keep each under `maxPixels` and as even
// as that allows; one row each when not even one fits (the backend then says so).
std::vector<PixelRegion> splitIntoTiles(const PixelRegion& region, uint64_t maxPixels);

class WavefrontRenderer {
public:
  // Loads the scene into `backend` and configures it for `settings`, with the paths in
  // flight lowered to what the device can hold, and the region cut into tiles when its
  // accumulation does not fit the device at once.
  WavefrontRenderer(Backend& backend, const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings);

  // Traces the samples [firstSample, sampleEnd()) of every pixel of the region (the
  // settings') that are not traced yet, calling afterPass with the figures so far after
  // each pass; when it returns false the render stops there, to go on by a later call
  // (possibly after resume() in another process). With several tiles, tile after tile:
  // each pixel's paths are the same as without tiles, so the image is the same bit for bit.
  // With a time limit (seconds of this call above 0; a single tile), passes are sized from
  // the time earlier ones took per path to end near it, and once it has passed the render
  // ends with the sample every pixel is in: each pixel then has the same whole number of
  // samples (at least one), and the image equals a render of that many bit for bit.
  RenderStats render(const std::function<bool(const RenderStats&)>& afterPass, double timeLimitSeconds = 0.0);
  // How many tiles the region is rendered in (1 when it fits the device at once).
  size_t tileCount() const { return tiles_.size(); }

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

  // Per-pixel mean radiance and the variance of that mean, from the samples so far, over the
  // region rendered.
  RadianceImage image();
  // The same from an accumulation read earlier (accumulation()).
  RadianceImage imageOf(const Accumulation& accumulation) const;

  // Where a render stands, for a checkpoint: the paths traced so far in render order (path
  // k is sample k / pixels of region pixel k % pixels, counted from sample 0; with tiles,
  // each tile's paths in that order after the tiles before it) and the per-pixel sums they
  // were accumulated into. Paths [firstSample * pixels, pathsDone()) are in the sums. A render
  // in tiles has no checkpoints: accumulation() and resume() require a single tile.
  uint64_t pathsDone() const { return pathsDone_; }
  uint64_t pathsEnd() const;
  Accumulation accumulation();
  // Continues a render from a checkpoint's state, made by a renderer of the same scene and
  // settings (the sums are loaded as they were, so the render goes on bit for bit).
  void resume(const Accumulation& accumulation, uint64_t pathsDone);

private:
  void runPass(uint32_t firstPixel, uint32_t firstSample, uint32_t pathCount, RenderStats& stats);
  // The paths of a pass of render(): the paths in flight, or fewer with adaptive sampling.
  uint64_t pathsPerPass() const;
  // Runs the next pass of at most `maxCount` paths, stopping at path index `end`, and
  // measures its seconds per path.
  void runNextPass(uint64_t end, uint64_t maxCount, RenderStats& stats);
  // Lowers pathsEnd() to the next whole number of samples per pixel (at least one): the
  // end of the sample every pixel is in. A single tile only (render() checks).
  void endWithSampleInProgress();
  void configure(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings);
  // Points the backend at tile `index` with an empty accumulation.
  void configureTile(size_t index);
  // The first path of tile `index` in render order, and the one after its last.
  uint64_t tileStart(size_t index) const;
  uint64_t tileEnd(size_t index) const;
  // Copies the current tile's sums into the region's (tiledSums_).
  void storeTile();

  Backend& backend_;
  RenderSettings settings_;
  gpu::RenderParams params_;  // its region and pixelCount are the current tile's
  std::vector<PixelRegion> tiles_;
  size_t tile_ = 0;            // the one configured
  Accumulation tiledSums_;     // with several tiles: the region's sums, finished tiles filled in
  // Paths traced, in render order: path k is sample k / pixels of region pixel k % pixels.
  // A render starts at path firstPath_ (sample settings.firstSample).
  uint64_t firstPath_ = 0;
  uint64_t pathsDone_ = 0;
  // The end endWithSampleInProgress set (a path index), or 0: the settings' end.
  uint64_t earlyEnd_ = 0;
  // Measured seconds per path of the last pass; 0 before the first.
  double secondsPerPath_ = 0.0;
};

}  // namespace wp
