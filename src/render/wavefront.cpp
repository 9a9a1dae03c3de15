// Sample passes of the wavefront path tracer: generate, then per bounce extend, shade,
// advance (GPU-written dispatch sizes) and connect, then accumulate.
#include "render/wavefront.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "bvh/gpu_scene.h"
#include "core/error.h"
#include "render/camera_lens.h"
#include "scene/scene.h"
#include "shaders/common/bsdf_models.h"
#include "shaders/common/layout.h"

namespace wp {

gpu::RenderParams makeRenderParams(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings) {
  gpu::RenderParams p{};
  p.camera = makeLens(scene.camera, settings.width, settings.height);
  p.sky = gpuScene.sky;
  if (!settings.skySampling) {
    p.sky.selectionProbability = 0.0f;  // the sky is then found by BSDF sampling alone
  }
  const PixelRegion region = settings.pixelRegion();
  p.width = settings.width;
  p.height = settings.height;
  p.pixelCount = uint32_t(region.pixels());
  p.seed = settings.seed;
  p.samplerKind = settings.sampler == SamplerKind::Sobol ? WP_SAMPLER_SOBOL : WP_SAMPLER_INDEPENDENT;
  p.regionX = region.x0;
  p.regionY = region.y0;
  p.regionWidth = region.width();
  p.regionHeight = region.height();
  p.maxBounces = settings.maxBounces;
  p.mode = settings.mode == IntegratorMode::Mis       ? WP_MODE_MIS
           : settings.mode == IntegratorMode::NeeOnly ? WP_MODE_NEE
                                                      : WP_MODE_BSDF;
  p.rouletteStart = settings.russianRouletteStart;
  p.lightCount = uint32_t(gpuScene.lights.size());
  p.planeCount = uint32_t(gpuScene.planes.size());
  p.topLevel = gpuScene.topLevelEntry();
  p.instanceCount = gpuScene.placedInstances;
  // p.maxPaths, the paths of a pass, depends on the device and the tile: set by configureTile.
  p.bsdfFlags = (settings.widenRoughness ? WP_BSDF_WIDEN_BECKMANN : 0u) |
                (settings.fixedLobeChoice ? WP_BSDF_FIXED_LOBE_CHOICE : 0u);
  p.contributionClamp = settings.contributionClamp;
  p.filterGlossy = settings.filterGlossy;
  p.lightSelection = settings.lightSelection == LightSelection::SolidAngle ? WP_LIGHT_SELECTION_SOLID_ANGLE
                                                                            : WP_LIGHT_SELECTION_POWER;
  p.punctualLightCount = gpuScene.punctualLightCount;
  p.adaptiveThreshold = settings.adaptiveThreshold;
  p.adaptiveMinSamples = settings.adaptiveMinSamples;
  p.emissionHittable = gpuScene.emissionHittable() ? 1u : 0u;
  p.featurePasses = settings.featurePasses ? 1u : 0u;
  return p;
}

uint32_t defaultPathsInFlight(bool onCpu) { return onCpu ? 1u << 20 : 65535u * WP_WORKGROUP_SIZE; }

std::vector<PixelRegion> splitIntoTiles(const PixelRegion& region, uint64_t maxPixels) {
  const uint32_t height = region.height();
  const uint64_t rowsPerTile = std::clamp<uint64_t>(maxPixels / region.width(), 1, height);
  const uint64_t count = (height + rowsPerTile - 1) / rowsPerTile;
  std::vector<PixelRegion> tiles;
  for (uint64_t i = 0; i < count; ++i) {
    const auto top = region.y0 + uint32_t(height * i / count);
    const auto bottom = region.y0 + uint32_t(height * (i + 1) / count);
    tiles.push_back({region.x0, top, region.x1, bottom});
  }
  return tiles;
}

WavefrontRenderer::WavefrontRenderer(Backend& backend, const Scene& scene, const GpuScene& gpuScene,
                                     const RenderSettings& settings)
    : backend_(backend) {
  backend_.loadScene(gpuScene);
  configure(scene, gpuScene, settings);
}

void WavefrontRenderer::configure(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings) {
  settings_ = settings;
  const uint32_t wanted = settings_.maxPaths != 0 ? settings_.maxPaths : defaultPathsInFlight(backend_.onCpu());
  settings_.maxPaths = std::min(wanted, backend_.maxPathsInFlight());
  params_ = makeRenderParams(scene, gpuScene, settings_);
  const PixelRegion region = settings_.pixelRegion();
  firstPath_ = region.pixels() * settings_.firstSample;
  pathsDone_ = firstPath_;
  earlyEnd_ = 0;
  tiles_ = splitIntoTiles(region, backend_.maxAccumulationPixels(settings_.maxPaths));
  tiledSums_ = {};
  if (tiles_.size() > 1) tiledSums_ = Accumulation::zeros(region.pixels());
  configureTile(0);
}

void WavefrontRenderer::configureTile(size_t index) {
  const PixelRegion& tile = tiles_[index];
  params_.regionX = tile.x0;
  params_.regionY = tile.y0;
  params_.regionWidth = tile.width();
  params_.regionHeight = tile.height();
  params_.pixelCount = uint32_t(tile.pixels());
  params_.maxPaths =
      uint32_t(std::clamp<uint64_t>(tile.pixels() * settings_.samplesInRange(), 1, settings_.maxPaths));
  backend_.configure(params_);
  tile_ = index;
}

uint64_t WavefrontRenderer::tileStart(size_t index) const {
  uint64_t start = firstPath_;
  for (size_t t = 0; t < index; ++t) start += tiles_[t].pixels() * settings_.samplesInRange();
  return start;
}

uint64_t WavefrontRenderer::tileEnd(size_t index) const {
  return tileStart(index) + tiles_[index].pixels() * settings_.samplesInRange();
}

void WavefrontRenderer::storeTile() {
  const Accumulation tile = backend_.readAccumulation();
  const PixelRegion region = settings_.pixelRegion();
  const size_t at = size_t(tiles_[tile_].y0 - region.y0) * region.width();  // tiles are bands of whole rows
  for (uint32_t layer = 0; layer < WP_ACCUMULATION_LAYERS; ++layer) {
    const std::vector<glm::vec4>& from = *tile.layers()[layer];
    std::copy(from.begin(), from.end(), tiledSums_.layers()[layer]->begin() + long(at));
  }
}

void WavefrontRenderer::resume(const Accumulation& accumulation, uint64_t pathsDone) {
  if (tiles_.size() > 1) throw std::logic_error("a render in tiles cannot resume a checkpoint");
  backend_.writeAccumulation(accumulation);
  pathsDone_ = pathsDone;
}

void WavefrontRenderer::restart(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings,
                                bool reloadScene) {
  if (reloadScene) {
    backend_.loadScene(gpuScene);
  }
  configure(scene, gpuScene, settings);
}

void WavefrontRenderer::runPass(uint32_t firstPixel, uint32_t firstSample, uint32_t pathCount, RenderStats& stats) {
  auto constants = [&](uint32_t bounce) { return gpu::PassConstants{firstPixel, firstSample, pathCount, bounce}; };
  // Vertices of bounce 0 .. maxBounces scatter; the rays they spawn reach bounce
  // maxBounces + 1, where only emission is gathered.
  const uint32_t bounces = settings_.maxBounces + 2;
  backend_.beginPass({pathCount, bounces});
  // Generate fills bounce 0's ray queue and sizes extend and shade to it; each advance sizes
  // connect of its bounce and extend and shade of the next (queues.h).
  backend_.dispatch({Kernel::Generate, constants(0), DispatchSize::fixed(pathCount), DispatchArguments::Written});
  if (params_.adaptiveThreshold > 0.0f) {
    // Generate appended only the rays of pixels still sampling: size bounce 0 to them.
    backend_.dispatch(
        {Kernel::Advance, constants(WP_AFTER_GENERATE), DispatchSize::fixed(1), DispatchArguments::Written});
  }
  for (uint32_t bounce = 0; bounce < bounces; ++bounce) {
    backend_.dispatch({Kernel::Extend, constants(bounce), DispatchSize::rayQueue()});
    backend_.dispatch({Kernel::Shade, constants(bounce), DispatchSize::rayQueue()});
    backend_.dispatch({Kernel::Advance, constants(bounce), DispatchSize::fixed(1), DispatchArguments::Written});
    backend_.dispatch({Kernel::Connect, constants(bounce), DispatchSize::shadowQueue()});
  }
  uint32_t pixels = params_.pixelCount;
  backend_.dispatch({Kernel::Accumulate, constants(0), DispatchSize::fixed(std::min(pathCount, pixels))});
  PassResult result = backend_.endPass();
  stats.extensionRays += result.extensionRays;
  stats.shadowRays += result.shadowRays;
  for (int k = 0; k < kKernelCount; ++k) {
    stats.kernelMs[k] += result.kernelMs[k];
  }
  ++stats.passes;
}

void WavefrontRenderer::runNextPass(uint64_t end, uint64_t maxCount, RenderStats& stats) {
  const auto passStart = std::chrono::steady_clock::now();
  // The current tile's pixels, and where the next path lies in its own render order.
  const uint64_t pixels = params_.pixelCount;
  const uint64_t stop = tiles_.size() > 1 ? std::min(end, tileEnd(tile_)) : end;
  const uint64_t path = pixels * settings_.firstSample + (pathsDone_ - tileStart(tile_));
  uint32_t count = uint32_t(std::min<uint64_t>({params_.maxPaths, maxCount, stop - pathsDone_}));
  runPass(uint32_t(path % pixels), uint32_t(path / pixels), count, stats);
  pathsDone_ += count;
  stats.samples += count;
  secondsPerPath_ = std::chrono::duration<double>(std::chrono::steady_clock::now() - passStart).count() / count;
}

uint64_t WavefrontRenderer::pathsPerPass() const {
  if (!(settings_.adaptiveThreshold > 0.0f)) return params_.maxPaths;
  // Adaptive sampling decides between passes which pixels the next one traces: a pass of a
  // few samples per pixel (as many as lie between two checks) lets it leave out pixels soon
  // after they stop, at the cost of more passes; kSmallestAdaptivePass paths at least keep
  // a small image's passes from being all overhead.
  constexpr uint64_t kSmallestAdaptivePass = 1u << 16;
  const uint64_t betweenChecks = uint64_t(params_.pixelCount) * WP_ADAPTIVE_INTERVAL;
  return std::min<uint64_t>(params_.maxPaths, std::max(betweenChecks, kSmallestAdaptivePass));
}

RenderStats WavefrontRenderer::render(const std::function<bool(const RenderStats&)>& afterPass,
                                      double timeLimitSeconds) {
  const bool timed = timeLimitSeconds > 0.0;
  if (timed && tiles_.size() > 1) throw std::logic_error("a render in tiles has no time limit");
  // A timed render's passes: the first this many paths, to measure the time a path takes;
  // then as many as fit the time left, but not fewer, so that no pass is mostly overhead.
  constexpr uint64_t kSmallestTimedPass = 1u << 16;
  RenderStats stats;
  auto start = std::chrono::steady_clock::now();
  while (pathsDone_ < pathsEnd()) {
    uint64_t count = pathsPerPass();
    if (timed && earlyEnd_ == 0) {
      // The time is not up yet (it ends the render below), so `fit` is above 0; a double,
      // since a limit of 1e300 seconds fits more paths than a uint64_t counts.
      const double fit = secondsPerPath_ > 0.0 ? (timeLimitSeconds - stats.seconds) / secondsPerPath_ : 0.0;
      if (fit < double(count)) count = std::clamp(uint64_t(fit), std::min(kSmallestTimedPass, count), count);
    }
    runNextPass(pathsEnd(), count, stats);
    if (tiles_.size() > 1 && pathsDone_ == tileEnd(tile_)) {
      storeTile();
      if (tile_ + 1 < tiles_.size()) configureTile(tile_ + 1);
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (timed && stats.seconds >= timeLimitSeconds) endWithSampleInProgress();
    if (afterPass && !afterPass(stats)) break;
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

uint64_t WavefrontRenderer::pathsEnd() const {
  const uint64_t end = settings_.pixelRegion().pixels() * settings_.sampleEnd();
  return earlyEnd_ != 0 ? std::min(end, earlyEnd_) : end;
}

void WavefrontRenderer::endWithSampleInProgress() {
  const uint64_t pixels = settings_.pixelRegion().pixels();
  const uint64_t samplesStarted = (pathsDone_ - firstPath_ + pixels - 1) / pixels;
  earlyEnd_ = firstPath_ + std::max<uint64_t>(samplesStarted, 1) * pixels;
}

RenderStats WavefrontRenderer::renderFor(double budgetSeconds, uint32_t samplesPerPixel) {
  if (tiles_.size() > 1) {
    throw Error("a " + std::to_string(settings_.width) + "x" + std::to_string(settings_.height) +
                " image does not fit " + backend_.deviceName() + " at once, and a progressive render cannot be split "
                "into tiles; make the window smaller");
  }
  RenderStats stats;
  auto start = std::chrono::steady_clock::now();
  const uint64_t end = uint64_t(params_.pixelCount) * samplesPerPixel;
  // Passes fill what is left of the budget at the measured rate, but never fall under
  // kSmallestPass paths, and the frame ends rather than run a pass under a quarter of the
  // budget: a small pass pays the fixed cost per pass (four dispatches per bounce) on few
  // paths, and the rate it measured would shrink the next passes in turn. The first pass,
  // with nothing measured yet, is the smallest: a whole pass of a CPU device could take
  // seconds.
  constexpr uint64_t kSmallestPass = 4096;
  while (pathsDone_ < end) {
    double left = budgetSeconds - stats.seconds;
    uint64_t count = kSmallestPass;
    if (secondsPerPath_ > 0.0) {
      if (stats.passes > 0 && left < 0.25 * budgetSeconds) break;
      count = std::max(kSmallestPass, uint64_t(left / secondsPerPath_));
    } else if (stats.passes > 0 && left <= 0.0) {
      break;
    }
    runNextPass(end, count, stats);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return stats;
}

uint32_t WavefrontRenderer::samplesPerPixelDone() const {
  return uint32_t((pathsDone_ - firstPath_) / settings_.pixelRegion().pixels());
}

Accumulation WavefrontRenderer::accumulation() {
  if (tiles_.size() > 1) throw std::logic_error("a render in tiles has no checkpoint");
  return backend_.readAccumulation();
}

RadianceImage WavefrontRenderer::image() {
  RadianceImage image = imageOf(tiles_.size() > 1 ? tiledSums_ : backend_.readAccumulation());
  // What a scene may hold is bounded (scene_limits.h, the loader's checks) so that no sum
  // overflows: a pixel that is not finite is a bug, said rather than written to a file.
  for (size_t i = 0; i < image.mean.size(); ++i) {
    const glm::vec3 both = image.mean[i] + image.variance[i];
    if (!std::isfinite(both.x) || !std::isfinite(both.y) || !std::isfinite(both.z)) {
      throw std::logic_error("the render produced a pixel that is not a finite number, (" +
                             std::to_string(i % image.width) + ", " + std::to_string(i / image.width) + ")");
    }
  }
  return image;
}

RadianceImage WavefrontRenderer::imageOf(const Accumulation& acc) const {
  RadianceImage image;
  const PixelRegion region = settings_.pixelRegion();
  image.width = region.width();
  image.height = region.height();
  size_t pixels = size_t(image.width) * image.height;
  image.mean.resize(pixels);
  image.variance.resize(pixels);
  // A render without feature passes has none to give (their sums are zero).
  const bool features = settings_.featurePasses;
  if (features) {
    image.albedo.resize(pixels);
    image.normal.resize(pixels);
    image.depth.resize(pixels);
  }
  // With adaptive sampling the pixels hold different numbers of samples, which the EXR keeps.
  if (settings_.adaptiveThreshold > 0.0f) image.sampleCount.resize(pixels);
  for (size_t i = 0; i < pixels; ++i) {
    // The samples the pixel holds: its own count (mid-pass in progressive rendering, or
    // stopped early by adaptive sampling, pixels differ).
    const float count = gpu::sampleCountOf(acc.sum[i]);
    if (!image.sampleCount.empty()) image.sampleCount[i] = count;
    double n = std::max(double(count), 1.0);
    glm::vec3 mean = glm::vec3(acc.sum[i]) / float(n);
    glm::vec3 meanSquare = glm::vec3(acc.sumSquares[i]) / float(n);
    // Unbiased sample variance, divided by n: the variance of the pixel's mean estimate.
    glm::vec3 sampleVariance = n > 1 ? glm::max(meanSquare - mean * mean, glm::vec3(0.0f)) * float(n / (n - 1)) : glm::vec3(0.0f);
    image.mean[i] = mean;
    image.variance[i] = sampleVariance / float(n);
    if (features) {
      image.albedo[i] = gpu::albedoSumOf(acc.albedoDepth[i]) / float(n);
      image.normal[i] = glm::vec3(acc.normal[i]) / float(n);
      image.depth[i] = gpu::depthSumOf(acc.albedoDepth[i]) / float(n);
    }
  }
  return image;
}

}  // namespace wp
