// Render settings: everything a user can choose about one render, in one place.
#pragma once

#include <cstdint>

namespace wp {

enum class IntegratorMode { Mis, NeeOnly, BsdfOnly };
enum class LightSelection { Power, SolidAngle };
// Where a path's random numbers come from (shaders/common/sampler.h, docs/sampling.md).
enum class SamplerKind { Sobol, Independent };

// A crop of the image: columns [x0, x1) and rows [y0, y1), in pixels from the top left.
struct PixelRegion {
  uint32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
  uint32_t width() const { return x1 - x0; }
  uint32_t height() const { return y1 - y0; }
  uint64_t pixels() const { return uint64_t(width()) * height(); }
  bool operator==(const PixelRegion&) const = default;
};

// The most samples a pixel may get (--spp's limit): a pixel's sums count samples in floats,
// exactly up to 2^24 (accumulation.h).
constexpr uint32_t kMaxSamplesPerPixel = 1u << 20;

struct RenderSettings {
  uint32_t width = 512;
  uint32_t height = 512;
  uint32_t samplesPerPixel = 64;
  // The samples of each pixel this render traces, [firstSample, endSample) of the
  // samplesPerPixel that make the frame (--samples A..B: one batch of a frame split over
  // machines); endSample 0 means samplesPerPixel.
  uint32_t firstSample = 0;
  uint32_t endSample = 0;
  // The pixels this render traces (--region); empty (x1 = 0) means the whole image. A pixel
  // gets the same samples whatever the region, so crops merge into the whole image exactly.
  PixelRegion region;
  // Cycles' "max bounces": 0 is direct light only; a path has at most maxBounces + 2
  // segments (camera ray, maxBounces bounces, and the segment that reaches the light).
  uint32_t maxBounces = 8;
  uint32_t seed = 0;
  // Owen-scrambled Sobol, stratified across each pixel's samples, or independent PCG
  // streams (the sampler before Sobol, kept for comparison).
  SamplerKind sampler = SamplerKind::Sobol;
  IntegratorMode mode = IntegratorMode::Mis;
  // First bounce at which Russian roulette may end a path. Short paths carry most of the
  // image's energy, and ending them early adds variance for little saved work.
  uint32_t russianRouletteStart = 3;
  // Paths in flight per sample pass: bounds GPU memory (about 200 bytes a path) whatever
  // the image size. 0: as many as suit the device (defaultPathsInFlight, wavefront.h).
  uint32_t maxPaths = 0;
  // Next event estimation samples the sky by its luminance (environment.h); off, only rays
  // that BSDF sampling sends out find it (to show what sky sampling is worth).
  bool skySampling = true;

  // Shading switches, all off by default (the default render is unbiased).
  // Sample glass's Beckmann normals from Walter et al.'s widened lobe (bsdf_models.h:
  // WP_BSDF_WIDEN_BECKMANN): the pdfs follow, so only the variance changes.
  bool widenRoughness = false;
  // For figures only: plastic picks its lobes 50/50 instead of by Fresnel (unbiased too;
  // bsdf_models.h: WP_BSDF_FIXED_LOBE_CHOICE).
  bool fixedLobeChoice = false;
  // How next event estimation picks a light: by power (alias table), or by the solid angle
  // each subtends from the shading point times its luminance (a pass over all lights).
  LightSelection lightSelection = LightSelection::Power;
  // Biased: scale each contribution but emission seen by the camera down to at most this
  // luminance (0 = off), trading energy for fewer fireflies.
  float contributionClamp = 0.0f;
  // Biased, as Cycles' Filter Glossy (its default 1; shaders/common/integrator.h): roughens the
  // glossy lobes a path reaches after unlikely bounces (0 = off).
  float filterGlossy = 0.0f;
  // Adaptive sampling (shaders/common/accumulation.h): from adaptiveMinSamples on, a pixel
  // whose estimated relative error is below adaptiveThreshold receives no more samples
  // (0: off, every pixel gets every sample).
  float adaptiveThreshold = 0.0f;
  uint32_t adaptiveMinSamples = 16;
  // Whether the render records feature passes (albedo, normal, depth: what an EXR holds for
  // denoisers). Off, their sums stay zero and the radiance is the same bit for bit, faster:
  // `wavepath render` turns it off for a PNG and for an EXR without passes; the viewer keeps
  // it (F12 saves an EXR too).
  bool featurePasses = true;

  uint32_t sampleEnd() const { return endSample == 0 ? samplesPerPixel : endSample; }
  uint32_t samplesInRange() const { return sampleEnd() - firstSample; }
  PixelRegion pixelRegion() const { return region.x1 == 0 ? PixelRegion{0, 0, width, height} : region; }
};

}  // namespace wp
