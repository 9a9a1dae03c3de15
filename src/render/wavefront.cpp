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

namespace wp {

gpu::RenderParams makeRenderParams(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings) {
  gpu::RenderParams p{};
  p.camera = makeLens(scene.camera, settings.width, settings.height);
  p.sky = gpuScene.sky;
  if (!settings.skySampling) {
    p.sky.transform.z = 0.0f;  // the sky is then found by BSDF sampling alone
  }
  uint32_t pixels = settings.width * settings.height;
  p.image = glm::uvec4(settings.width, settings.height, pixels, settings.seed);
  uint32_t mode = settings.mode == IntegratorMode::Mis       ? WP_MODE_MIS
                  : settings.mode == IntegratorMode::NeeOnly ? WP_MODE_NEE
                                                             : WP_MODE_BSDF;
  p.mode = glm::uvec4(settings.maxBounces, mode, settings.russianRouletteStart, uint32_t(gpuScene.lights.size()));
  uint64_t totalPaths = uint64_t(pixels) * settings.samplesPerPixel;
  uint32_t maxPaths = uint32_t(std::clamp<uint64_t>(totalPaths, 1, settings.maxPaths));
  p.counts = glm::uvec4(uint32_t(gpuScene.planes.size()), gpuScene.tlasRoot, gpuScene.placedInstances,
                        maxPaths);
  uint32_t bsdfFlags = (settings.widenRoughness ? WP_BSDF_WIDEN_BECKMANN : 0u) |
                       (settings.fixedLobeChoice ? WP_BSDF_FIXED_LOBE_CHOICE : 0u);
  uint32_t lightSelection = settings.lightSelection == LightSelection::SolidAngle ? WP_LIGHT_SELECTION_SOLID_ANGLE
                                                                                  : WP_LIGHT_SELECTION_POWER;
  p.shading = glm::uvec4(bsdfFlags, glm::floatBitsToUint(settings.contributionClamp), lightSelection, 0u);
  p.tile = glm::uvec4(0u, 0u, settings.width, settings.height);
  return p;
}

std::vector<Tile> splitIntoTiles(uint32_t width, uint32_t height, uint64_t maxPixels) {
  const uint64_t rowsPerTile = std::clamp<uint64_t>(maxPixels / width, 1, height);
  const uint64_t count = (height + rowsPerTile - 1) / rowsPerTile;
  std::vector<Tile> tiles;
  for (uint64_t i = 0; i < count; ++i) {
    const auto top = uint32_t(height * i / count);
    const auto bottom = uint32_t(height * (i + 1) / count);
    tiles.push_back({0, top, width, bottom - top});
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
  settings_.maxPaths = std::min(settings_.maxPaths, backend_.maxPathsInFlight());
  params_ = makeRenderParams(scene, gpuScene, settings_);
  tiles_ = splitIntoTiles(settings_.width, settings_.height, backend_.maxAccumulationPixels(settings_.maxPaths));
  image_ = {};
  configureTile(0);
}

void WavefrontRenderer::configureTile(size_t index) {
  const Tile& tile = tiles_[index];
  const uint32_t pixels = tile.width * tile.height;
  params_.tile = glm::uvec4(tile.x, tile.y, tile.width, tile.height);
  params_.image.z = pixels;
  params_.counts.w = uint32_t(std::clamp<uint64_t>(uint64_t(pixels) * settings_.samplesPerPixel, 1, settings_.maxPaths));
  backend_.configure(params_);
  tile_ = index;
  pathsDone_ = 0;
}

void WavefrontRenderer::restart(const Scene& scene, const GpuScene& gpuScene, const RenderSettings& settings,
                                bool reloadScene) {
  if (reloadScene) {
    backend_.loadScene(gpuScene);
  }
  configure(scene, gpuScene, settings);
}

void WavefrontRenderer::runPass(uint32_t firstPixel, uint32_t firstSample, uint32_t pathCount, RenderStats& stats) {
  auto constants = [&](uint32_t bounce) {
    gpu::PassConstants c;
    c.pass = glm::uvec4(firstPixel, firstSample, pathCount, bounce);
    return c;
  };
  backend_.beginPass();
  backend_.dispatch(Kernel::Generate, constants(0), DispatchSize::fixed(pathCount));
  // Vertices of bounce 0 .. maxBounces scatter; the rays they spawn reach bounce
  // maxBounces + 1, where only emission is gathered.
  for (uint32_t bounce = 0; bounce <= settings_.maxBounces + 1; ++bounce) {
    backend_.dispatch(Kernel::Extend, constants(bounce), DispatchSize::rayQueue());
    backend_.dispatch(Kernel::Shade, constants(bounce), DispatchSize::rayQueue());
    backend_.dispatch(Kernel::Advance, constants(bounce), DispatchSize::fixed(1));
    backend_.dispatch(Kernel::Connect, constants(bounce), DispatchSize::shadowQueue());
  }
  uint32_t pixels = params_.image.z;
  backend_.dispatch(Kernel::Accumulate, constants(0), DispatchSize::fixed(std::min(pathCount, pixels)));
  PassResult result = backend_.endPass();
  stats.extensionRays += result.extensionRays;
  stats.shadowRays += result.shadowRays;
  for (int k = 0; k < kKernelCount; ++k) {
    stats.kernelMs[k] += result.kernelMs[k];
  }
  ++stats.passes;
}

void WavefrontRenderer::runNextPass(uint64_t end, uint64_t maxCount, RenderStats& stats) {
  const uint64_t pixels = params_.image.z;
  uint32_t count = uint32_t(std::min<uint64_t>({params_.counts.w, maxCount, end - pathsDone_}));
  runPass(uint32_t(pathsDone_ % pixels), uint32_t(pathsDone_ / pixels), count, stats);
  pathsDone_ += count;
  stats.samples += count;
}

RenderStats WavefrontRenderer::render(const std::function<void(double)>& progress) {
  RenderStats stats;
  auto start = std::chrono::steady_clock::now();
  const uint64_t total = uint64_t(settings_.width) * settings_.height * settings_.samplesPerPixel;
  const bool tiled = tiles_.size() > 1;
  if (tiled) {
    image_.width = settings_.width;
    image_.height = settings_.height;
    image_.mean.resize(size_t(image_.width) * image_.height);
    image_.variance.resize(image_.mean.size());
  }
  for (size_t t = tiled ? 0 : tile_; t < tiles_.size(); ++t) {
    if (t != tile_ || tiled) configureTile(t);
    const uint64_t end = pathsDone_ + uint64_t(params_.image.z) * settings_.samplesPerPixel;
    while (pathsDone_ < end) {
      runNextPass(end, params_.counts.w, stats);
      if (progress) {
        progress(double(stats.samples) / double(total));
      }
    }
    if (tiled) {
      const RadianceImage part = tileImage();
      const Tile& tile = tiles_[t];
      for (uint32_t row = 0; row < tile.height; ++row) {
        const size_t from = size_t(row) * tile.width;
        const size_t to = size_t(tile.y + row) * image_.width + tile.x;
        std::copy_n(part.mean.begin() + from, tile.width, image_.mean.begin() + to);
        std::copy_n(part.variance.begin() + from, tile.width, image_.variance.begin() + to);
      }
    }
  }
  stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return stats;
}

RenderStats WavefrontRenderer::renderFor(double budgetSeconds, uint32_t samplesPerPixel) {
  if (tiles_.size() > 1) {
    throw Error("a " + std::to_string(settings_.width) + "x" + std::to_string(settings_.height) +
                " image does not fit " + backend_.deviceName() + " at once, and a progressive render cannot be split "
                "into tiles; make the window smaller");
  }
  RenderStats stats;
  auto start = std::chrono::steady_clock::now();
  const uint64_t end = uint64_t(params_.image.z) * samplesPerPixel;
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
    uint64_t before = pathsDone_;
    double passStart = stats.seconds;
    runNextPass(end, count, stats);
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    secondsPerPath_ = (stats.seconds - passStart) / double(pathsDone_ - before);
  }
  return stats;
}

uint32_t WavefrontRenderer::samplesPerPixelDone() const { return uint32_t(pathsDone_ / params_.image.z); }

RadianceImage WavefrontRenderer::image() {
  RadianceImage image = tiles_.size() > 1 ? std::move(image_) : tileImage();
  // What a scene may hold is bounded (radiance_limit.h, the loader's checks) so that no sum
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

RadianceImage WavefrontRenderer::tileImage() {
  Accumulation acc = backend_.readAccumulation();
  RadianceImage image;
  image.width = params_.tile.z;
  image.height = params_.tile.w;
  size_t pixels = size_t(image.width) * image.height;
  image.mean.resize(pixels);
  image.variance.resize(pixels);
  const uint64_t fullSamples = pathsDone_ / pixels, startedPixels = pathsDone_ % pixels;
  for (size_t i = 0; i < pixels; ++i) {
    // Mid-pass (progressive rendering), the first startedPixels pixels have one more sample.
    double n = double(std::max<uint64_t>(fullSamples + (i < startedPixels ? 1 : 0), 1));
    glm::vec3 mean = glm::vec3(acc.sum[i]) / float(n);
    glm::vec3 meanSquare = glm::vec3(acc.sumSquares[i]) / float(n);
    // Unbiased sample variance, divided by n: the variance of the pixel's mean estimate.
    glm::vec3 sampleVariance = n > 1 ? glm::max(meanSquare - mean * mean, glm::vec3(0.0f)) * float(n / (n - 1)) : glm::vec3(0.0f);
    image.mean[i] = mean;
    image.variance[i] = sampleVariance / float(n);
  }
  return image;
}

}  // namespace wp
