// Tests of the Sobol sampler the GPU runs (sobol.h, sampler.h): the Pascal dimension against
// the direction-number recurrence, the four-lane draws against Burley's scalar algorithm,
// stratification of every power-of-two prefix, uniformity and independence over scrambles
// (chi-square), the convergence rate on smooth integrands, and a vertex's and a camera ray's
// draws at once against the same draws one at a time.
#include "shaders/common/sampler.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "support/chi_square.h"

namespace {

namespace gpu = wp::gpu;
using wp::test::chiSquareTest;

// The chi-square tests below, each at the Šidák-corrected level, so that a correct sampler
// fails the suite with probability 1% over the choice of seeds (fixed: deterministic).
constexpr int kChiSquareTests = 6;
const double kAlpha = wp::test::sidakAlpha(0.01, kChiSquareTests);
constexpr uint32_t kRenderSeed = 7;

gpu::PathSamples pixelSamples(uint32_t sampler, uint32_t pixel, uint32_t sampleIndex) {
  return gpu::startPathSamples(sampler, pixel, sampleIndex, kRenderSeed);
}

glm::vec2 sobolPoint(uint32_t pixel, uint32_t sampleIndex, uint32_t dimension) {
  return gpu::drawPath2(WP_SAMPLER_SOBOL, pixelSamples(WP_SAMPLER_SOBOL, pixel, sampleIndex), dimension).u;
}

float sobolNumber(uint32_t pixel, uint32_t sampleIndex, uint32_t dimension) {
  return gpu::drawPath1(WP_SAMPLER_SOBOL, pixelSamples(WP_SAMPLER_SOBOL, pixel, sampleIndex), dimension).u;
}

wp::test::ChiSquareResult uniformityOf(const std::vector<glm::vec2>& points, int bins) {
  std::vector<double> observed(size_t(bins) * bins, 0.0);
  for (glm::vec2 p : points) {
    EXPECT_TRUE(p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f) << p.x << ", " << p.y;
    observed[size_t(int(p.y * bins)) * bins + int(p.x * bins)] += 1.0;
  }
  return chiSquareTest(observed, std::vector<double>(observed.size(), double(points.size()) / observed.size()));
}

// The second Sobol dimension from its definition: primitive polynomial x + 1 (degree 1,
// initial direction number m1 = 1), direction numbers v_k = v_{k-1} ^ (v_{k-1} >> 1) as
// 32-bit fractions, and point i the XOR of v_k over the set bits k of i.
uint32_t sobolSecondDimension(uint32_t index) {
  uint32_t v = 1u << 31, x = 0;
  for (; index != 0; index >>= 1, v ^= v >> 1)
    if (index & 1u) x ^= v;
  return x;
}

TEST(Sobol, PascalDimensionMatchesTheDirectionNumbers) {
  for (uint32_t i = 0; i < 70000; ++i)
    ASSERT_EQ(gpu::reverseBits(gpu::sobolPascalReversed(i)), sobolSecondDimension(i)) << "index " << i;
  for (uint32_t i : {0x80000000u, 0xdeadbeefu, 0xffffffffu})
    EXPECT_EQ(gpu::reverseBits(gpu::sobolPascalReversed(i)), sobolSecondDimension(i)) << "index " << i;
}

// Burley 2020's shuffled, Owen-scrambled 2D Sobol point, one coordinate at a time in scalar
// code, as sobol.h computed it before it drew four lanes at once.
uint32_t laineKarras(uint32_t x, uint32_t seed) {
  x += seed;
  x ^= x * 0x6c50b47cu;
  x ^= x * 0xb82f1e52u;
  x ^= x * 0xc7afe638u;
  x ^= x * 0x8d22f6e6u;
  return x;
}
float owenScrambled(uint32_t reversedFraction, uint32_t seed) {
  return float(gpu::reverseBits(laineKarras(reversedFraction, seed)) >> 8u) * 5.9604644775390625e-8f;
}
glm::vec2 referenceSobol2(uint32_t index, uint32_t seed) {
  const uint32_t shuffled = gpu::reverseBits(laineKarras(gpu::reverseBits(index), seed));
  return {owenScrambled(shuffled, gpu::pcgHash(seed ^ 0x2c1b3c6du)),
          owenScrambled(gpu::sobolPascalReversed(shuffled), gpu::pcgHash(seed ^ 0x297a2d39u))};
}

TEST(Sobol, FourLanesAreBurleysScalarDraws) {
  for (uint32_t index : {0u, 1u, 2u, 3u, 255u, 256u, 65535u, 0x12345678u, 0xffffffffu}) {
    for (uint32_t seed : {0u, 1u, 0x9e3779b9u, 0xdeadbeefu}) {
      const glm::vec4 lanes = gpu::sobolScrambled4(index, glm::uvec4(seed, seed + 1u, seed + 2u, seed + 3u),
                                                   glm::uvec4(WP_SOBOL_FIRST, WP_SOBOL_SECOND, WP_SOBOL_SECOND,
                                                              WP_SOBOL_FIRST));
      EXPECT_EQ(lanes.x, referenceSobol2(index, seed).x) << index << ", " << seed;
      EXPECT_EQ(lanes.y, referenceSobol2(index, seed + 1u).y) << index << ", " << seed;
      EXPECT_EQ(lanes.z, referenceSobol2(index, seed + 2u).y) << index << ", " << seed;
      EXPECT_EQ(lanes.w, referenceSobol2(index, seed + 3u).x) << index << ", " << seed;
      EXPECT_EQ(gpu::sobolScrambled2(index, seed), referenceSobol2(index, seed));
      EXPECT_EQ(gpu::sobolScrambled1(index, seed), referenceSobol2(index, seed).x);
    }
  }
}

// A (0, m, 2)-net in base 2: each of the 2^m boxes of every shape 2^-a x 2^-(m-a) holds
// exactly one of the 2^m points. Checked for the first 2^m samples of several pixels and
// dimensions, so the shuffle, the scrambles and the padding all keep the stratification.
TEST(Sobol, EveryPowerOfTwoPrefixOfAPixelIsANet) {
  for (uint32_t pixel : {0u, 1u, 4321u, 262143u}) {
    for (uint32_t dimension : {WP_DIM_FILM, gpu::vertexDimension(5) + WP_DIM_BSDF_DIRECTION}) {
      for (int m = 1; m <= 10; ++m) {
        const uint32_t n = 1u << m;
        for (int a = 0; a <= m; ++a) {
          std::vector<int> boxes(n, 0);
          for (uint32_t s = 0; s < n; ++s) {
            glm::vec2 p = sobolPoint(pixel, s, dimension);
            const uint32_t bx = uint32_t(p.x * float(1u << a)), by = uint32_t(p.y * float(1u << (m - a)));
            ++boxes[(by << a) | bx];
          }
          for (uint32_t b = 0; b < n; ++b)
            ASSERT_EQ(boxes[b], 1) << "pixel " << pixel << " dimension " << dimension << ": " << n
                                   << " samples, boxes 2^-" << a << " x 2^-" << (m - a) << ", box " << b;
        }
      }
    }
  }
}

// Over the pixels (the scrambles), any one sample is uniform on the square and in 1D.
TEST(Sobol, ASampleIsUniformOverPixels) {
  for (uint32_t sampleIndex : {0u, 13u}) {
    std::vector<glm::vec2> points;
    for (uint32_t pixel = 0; pixel < 200000; ++pixel) points.push_back(sobolPoint(pixel, sampleIndex, WP_DIM_LENS));
    auto result = uniformityOf(points, 32);
    EXPECT_TRUE(result.accepts(kAlpha)) << "sample " << sampleIndex << ": " << result.describe();
  }
  std::vector<double> observed(64, 0.0);
  for (uint32_t pixel = 0; pixel < 200000; ++pixel) observed[int(sobolNumber(pixel, 3, WP_DIM_TIME) * 64)] += 1.0;
  auto result = chiSquareTest(observed, std::vector<double>(64, 200000.0 / 64));
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

// Padding: two dimensions of the same pixel's samples are independent (equal shuffles or
// scrambles would put the pairs on a curve), within a vertex and across vertices.
TEST(Sobol, DimensionsOfAPixelAreIndependent) {
  const uint32_t light = gpu::vertexDimension(0) + WP_DIM_LIGHT_CHOICE;
  const uint32_t roulette = gpu::vertexDimension(0) + WP_DIM_ROULETTE;
  const uint32_t nextLight = gpu::vertexDimension(1) + WP_DIM_LIGHT_CHOICE;
  for (uint32_t other : {roulette, nextLight}) {
    std::vector<glm::vec2> pairs;
    for (uint32_t s = 0; s < 65536; ++s) pairs.emplace_back(sobolNumber(99, s, light), sobolNumber(99, s, other));
    auto result = uniformityOf(pairs, 32);
    EXPECT_TRUE(result.accepts(kAlpha)) << "dimension " << other << ": " << result.describe();
  }
}

// The relative RMSE over 64 pixels (scrambles) of the N-sample estimate of the integral of
// f over the unit square, for N = 16 .. 4096, and the slope of log error against log N.
double convergenceSlope(uint32_t sampler, const std::function<double(glm::vec2)>& f, double exact) {
  std::vector<double> logN, logError;
  for (uint32_t n = 16; n <= 4096; n *= 4) {
    double squared = 0.0;
    for (uint32_t pixel = 0; pixel < 64; ++pixel) {
      double sum = 0.0;
      for (uint32_t s = 0; s < n; ++s)
        sum += f(gpu::drawPath2(sampler, pixelSamples(sampler, pixel, s), WP_DIM_FILM).u);
      squared += std::pow(sum / n - exact, 2.0);
    }
    logN.push_back(std::log(double(n)));
    logError.push_back(std::log(std::sqrt(squared / 64) / exact));
  }
  double meanX = 0, meanY = 0;
  for (size_t i = 0; i < logN.size(); ++i) meanX += logN[i] / logN.size(), meanY += logError[i] / logN.size();
  double sxy = 0, sxx = 0;
  for (size_t i = 0; i < logN.size(); ++i)
    sxy += (logN[i] - meanX) * (logError[i] - meanY), sxx += (logN[i] - meanX) * (logN[i] - meanX);
  return sxy / sxx;
}

// Owen-scrambled nets integrate smooth functions with error O(N^-1.5); independent samples
// only O(N^-0.5). The bound -1.0 leaves room for the noise of 64 scrambles, and the
// independent sampler, measured the same way, must sit near -0.5, so the test tells them apart.
TEST(Sobol, ErrorFallsFasterThanMonteCarloOnSmoothIntegrands) {
  // A smooth bump over the pixel (a Gaussian filter's shape) and a product of cosines.
  auto bump = [](glm::vec2 p) { return std::exp(-4.0 * (std::pow(p.x - 0.5, 2.0) + std::pow(p.y - 0.5, 2.0))); };
  const double bumpExact = std::pow(std::sqrt(M_PI / 4.0) * std::erf(1.0), 2.0);
  auto waves = [](glm::vec2 p) { return (1.5 + std::cos(3.0 * p.x)) * (1.5 + std::cos(2.0 * p.y)); };
  const double wavesExact = (1.5 + std::sin(3.0) / 3.0) * (1.5 + std::sin(2.0) / 2.0);
  for (auto [f, exact] : {std::pair{std::function<double(glm::vec2)>(bump), bumpExact},
                          std::pair{std::function<double(glm::vec2)>(waves), wavesExact}}) {
    const double sobol = convergenceSlope(WP_SAMPLER_SOBOL, f, exact);
    EXPECT_LT(sobol, -1.0) << "Sobol's error should fall about as N^-1.5";
    const double independent = convergenceSlope(WP_SAMPLER_INDEPENDENT, f, exact);
    EXPECT_NEAR(independent, -0.5, 0.15) << "independent samples' error should fall as N^-0.5";
  }
}

// The independent sampler draws a path's numbers in stream order, as before the Sobol one
// existed (so --sampler independent renders the images it rendered then).
TEST(Sampler, IndependentDrawsFollowTheStream) {
  gpu::PathSamples p = pixelSamples(WP_SAMPLER_INDEPENDENT, 12, 34);
  uint32_t state = gpu::rngSeed(12, 34, kRenderSeed);
  gpu::PathDraw3 d = gpu::drawPath3(WP_SAMPLER_INDEPENDENT, p, 17);
  for (int i = 0; i < 3; ++i) {
    state = gpu::rngNext(state);
    EXPECT_EQ(d.u[i], gpu::rngFloat(state)) << "draw " << i;
  }
  EXPECT_EQ(d.samples.state, state);
}

// shade draws a vertex's seven numbers at once (drawVertex) and generate a camera ray's five
// (drawCamera): each must be the number its dimension gives alone, and the independent
// stream must move on exactly as the draws one after another move it.
TEST(Sampler, VertexDrawsAreTheDrawsOfEachDimension) {
  for (uint32_t sampler : {uint32_t(WP_SAMPLER_SOBOL), uint32_t(WP_SAMPLER_INDEPENDENT)}) {
    for (uint32_t sampleIndex : {0u, 5u, 1023u}) {
      for (uint32_t bounce : {0u, 1u, 7u}) {
        for (bool light : {false, true}) {
          for (bool roulette : {false, true}) {
            gpu::PathSamples p = pixelSamples(sampler, 4321, sampleIndex);
            const gpu::VertexDraws d = gpu::drawVertex(sampler, p, bounce, light, roulette);
            const uint32_t first = gpu::vertexDimension(bounce);
            const gpu::PathDraw3 l = gpu::drawPath3(sampler, p, first + WP_DIM_LIGHT_CHOICE);
            if (light) p = l.samples;
            const gpu::PathDraw3 b = gpu::drawPath3(sampler, p, first + WP_DIM_BSDF_LOBE);
            p = b.samples;
            const gpu::PathDraw1 r = gpu::drawPath1(sampler, p, first + WP_DIM_ROULETTE);
            if (roulette) p = r.samples;
            // Sobol draws every number (its samples do not move); the independent stream
            // only those asked for, the others 0.
            const bool sobol = sampler == WP_SAMPLER_SOBOL;
            const std::string where = "sampler " + std::to_string(sampler) + ", sample " +
                                      std::to_string(sampleIndex) + ", bounce " + std::to_string(bounce);
            EXPECT_EQ(d.light, light || sobol ? l.u : glm::vec3(0.0f)) << where;
            EXPECT_EQ(d.bsdf, b.u) << where;
            EXPECT_EQ(d.roulette, roulette || sobol ? r.u : 0.0f) << where;
            EXPECT_EQ(d.samples.state, p.state) << where;
            EXPECT_EQ(d.samples.sampleIndex, p.sampleIndex) << where;
          }
        }
      }
    }
  }
}

TEST(Sampler, CameraDrawsAreTheDrawsOfEachDimension) {
  for (uint32_t sampler : {uint32_t(WP_SAMPLER_SOBOL), uint32_t(WP_SAMPLER_INDEPENDENT)}) {
    for (uint32_t sampleIndex : {0u, 5u, 1023u}) {
      const gpu::PathSamples p = pixelSamples(sampler, 77, sampleIndex);
      const gpu::CameraDraws d = gpu::drawCamera(sampler, p);
      const gpu::PathDraw2 film = gpu::drawPath2(sampler, p, WP_DIM_FILM);
      const gpu::PathDraw2 lens = gpu::drawPath2(sampler, film.samples, WP_DIM_LENS);
      EXPECT_EQ(d.time, gpu::pathTime(sampler, p));
      EXPECT_EQ(d.film, film.u);
      EXPECT_EQ(d.lens, lens.u);
      EXPECT_EQ(d.samples.state, lens.samples.state);
    }
  }
}

}  // namespace
