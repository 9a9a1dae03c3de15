// Tests of the physical camera's portable code: exposure at known settings, tone curves at
// known values and monotone, the thin lens's focus and circle of confusion, and uniform
// aperture sampling (chi-square).
#include "shaders/common/thin_lens.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <utility>
#include <vector>

#include "shaders/common/exposure.h"
#include "shaders/common/tone_curves.h"
#include "support/chi_square.h"

namespace {

namespace gpu = wp::gpu;
using wp::test::chiSquareTest;
using wp::test::TestRandom;

constexpr double kPi = 3.14159265358979323846;

// The sizes std140/std430 and OpenCL give the structs, so they can be uploaded as they are.
static_assert(sizeof(gpu::ThinLens) == 80);

// ---- Exposure ------------------------------------------------------------------------------

TEST(Exposure, Ev100AtKnownSettings) {
  // "Sunny 16": f/16, 1/100 s, ISO 100 gives log2(100 * 256 / (0.01 * 100)) = log2(25600).
  EXPECT_NEAR(gpu::ev100FromSettings(16.0f, 0.01f, 100.0f), 14.643856, 1e-5);
  EXPECT_NEAR(gpu::ev100FromSettings(1.0f, 1.0f, 100.0f), 0.0, 1e-6);
  // Doubling the ISO or the shutter time, or opening up one stop, is one EV less.
  EXPECT_NEAR(gpu::ev100FromSettings(16.0f, 0.01f, 200.0f), 13.643856, 1e-5);
  EXPECT_NEAR(gpu::ev100FromSettings(16.0f, 0.02f, 100.0f), 13.643856, 1e-5);
  EXPECT_NEAR(gpu::ev100FromSettings(16.0f / std::sqrt(2.0f), 0.01f, 100.0f), 13.643856, 1e-5);
}

TEST(Exposure, MaxLuminanceAtKnownSettings) {
  // Lmax = 78 N^2 / (S q t) = 78 * 256 / (100 * 0.65 * 0.01) = 30720 cd/m^2.
  EXPECT_NEAR(gpu::maxLuminanceFromSettings(16.0f, 0.01f, 100.0f), 30720.0, 0.01);
  EXPECT_NEAR(gpu::maxLuminanceFromSettings(2.0f, 0.5f, 400.0f), 78.0 * 4.0 / (400.0 * 0.65 * 0.5), 1e-5);
  // Through EV100 it is 1.2 * 2^EV100 whatever (N, t, S) gave that EV100.
  EXPECT_NEAR(gpu::maxLuminanceFromEv100(0.0f), 1.2, 1e-6);
  for (float n : {1.4f, 2.8f, 8.0f, 22.0f})
    for (float t : {1.0f / 1000.0f, 1.0f / 60.0f, 2.0f})
      for (float s : {50.0f, 100.0f, 3200.0f}) {
        double fromSettings = gpu::maxLuminanceFromSettings(n, t, s);
        double fromEv = gpu::maxLuminanceFromEv100(gpu::ev100FromSettings(n, t, s));
        EXPECT_NEAR(fromEv / fromSettings, 1.0, 1e-5) << n << " " << t << " " << s;
        EXPECT_NEAR(gpu::ev100FromMaxLuminance(float(fromSettings)), gpu::ev100FromSettings(n, t, s), 1e-4);
      }
  EXPECT_FLOAT_EQ(gpu::exposureScale(30720.0f), 1.0f / 30720.0f);
}

TEST(Exposure, AutoExposureMapsLogAverageToMiddleGrey) {
  // A uniform image of luminance L: the scale takes L (plus epsilon) to the key 0.18.
  for (float l : {0.01f, 1.0f, 5000.0f}) {
    glm::vec3 radiance(l);  // grey, so its luminance is l
    float scale = gpu::autoExposureScale(gpu::logLuminance(radiance));
    EXPECT_NEAR(scale * (l + 1e-4f), 0.18, 1e-5) << l;
  }
  // Half black, half L: the geometric mean of epsilon and L + epsilon.
  float l = 100.0f;
  float mean = 0.5f * (gpu::logLuminance(glm::vec3(0.0f)) + gpu::logLuminance(glm::vec3(l)));
  EXPECT_NEAR(gpu::autoExposureScale(mean), 0.18 / std::sqrt(1e-4 * (l + 1e-4)), 1e-3);
  // Invalid radiance counts as black rather than poisoning the average.
  EXPECT_FLOAT_EQ(gpu::logLuminance(glm::vec3(-1.0f)), std::log(1e-4f));
  EXPECT_FLOAT_EQ(gpu::logLuminance(glm::vec3(std::nanf(""))), std::log(1e-4f));
}

// ---- Tone curves ---------------------------------------------------------------------------

TEST(ToneCurves, KnownValues) {
  EXPECT_FLOAT_EQ(gpu::toneMapChannel(0.5f, WP_TONE_CLAMP), 0.5f);
  EXPECT_FLOAT_EQ(gpu::toneMapChannel(2.0f, WP_TONE_CLAMP), 1.0f);
  EXPECT_FLOAT_EQ(gpu::toneMapChannel(1.0f, WP_TONE_REINHARD), 0.5f);
  EXPECT_FLOAT_EQ(gpu::toneMapChannel(3.0f, WP_TONE_REINHARD), 0.75f);
  // Hable's curve divided by its value at W = 11.2 (values from the formula in double).
  EXPECT_NEAR(gpu::toneMapChannel(0.18f, WP_TONE_HABLE), 0.0671098, 1e-6);
  EXPECT_NEAR(gpu::toneMapChannel(1.0f, WP_TONE_HABLE), 0.3043006, 1e-6);
  EXPECT_NEAR(gpu::toneMapChannel(4.0f, WP_TONE_HABLE), 0.7132380, 1e-6);
  EXPECT_NEAR(gpu::toneMapChannel(0.18f, WP_TONE_ACES), 0.2668989, 1e-6);
  EXPECT_NEAR(gpu::toneMapChannel(1.0f, WP_TONE_ACES), 0.8037975, 1e-6);
  EXPECT_NEAR(gpu::toneMapChannel(2.0f, WP_TONE_ACES), 0.9148551, 1e-6);
  for (unsigned mapper = WP_TONE_CLAMP; mapper <= WP_TONE_ACES; ++mapper) {
    // Black stays black (Hable's toe cancels to within float rounding, 1e-8).
    float black = gpu::toneMapChannel(0.0f, mapper);
    EXPECT_NEAR(black, 0.0f, 1e-7f) << mapper;
    EXPECT_EQ(gpu::toneMapChannel(-3.0f, mapper), black) << mapper;
    EXPECT_EQ(gpu::toneMapChannel(std::nanf(""), mapper), black) << mapper;
    EXPECT_EQ(gpu::toneMapChannel(1e30f, mapper), 1.0f) << mapper;
    EXPECT_EQ(gpu::toneMapChannel(std::numeric_limits<float>::infinity(), mapper), 1.0f) << mapper;
  }
  glm::vec3 mapped = gpu::toneMap(glm::vec3(1.0f, 3.0f, -1.0f), WP_TONE_REINHARD);
  EXPECT_EQ(mapped, glm::vec3(0.5f, 0.75f, 0.0f));
}

TEST(ToneCurves, HableMapsWhitePointToOne) {
  EXPECT_FLOAT_EQ(gpu::toneHable(WP_HABLE_WHITE), 1.0f);
  EXPECT_EQ(gpu::toneHable(2.0f * WP_HABLE_WHITE), 1.0f);
  EXPECT_LT(gpu::toneHable(0.99f * WP_HABLE_WHITE), 1.0f);
  EXPECT_FLOAT_EQ(gpu::hableCurve(0.0f) + 1.0f, 1.0f);  // the toe starts at black
}

TEST(ToneCurves, MonotoneAndInRange) {
  // 0 to 1000 in steps fine enough to see any dip: 1e-4 near 0, relative 1e-4 above 1.
  std::vector<float> xs;
  for (float x = 0.0f; x < 1.0f; x += 1e-4f) xs.push_back(x);
  for (float x = 1.0f; x < 1000.0f; x *= 1.0001f) xs.push_back(x);
  for (unsigned mapper = WP_TONE_CLAMP; mapper <= WP_TONE_ACES; ++mapper) {
    float previous = gpu::toneMapChannel(xs.front(), mapper);
    int strictRises = 0;
    for (float x : xs) {
      float y = gpu::toneMapChannel(x, mapper);
      ASSERT_GE(y, previous) << "mapper " << mapper << " dips at " << x;
      ASSERT_GE(y, 0.0f);
      ASSERT_LE(y, 1.0f);
      strictRises += y > previous;
      previous = y;
    }
    EXPECT_GT(strictRises, 1000) << mapper;  // rising, not flat
  }
}

TEST(Transfer, GammaAndSrgb) {
  EXPECT_NEAR(gpu::linearToGamma(0.5f, WP_DEFAULT_GAMMA), 0.7297401, 1e-6);
  EXPECT_EQ(gpu::encodeTransfer(glm::vec3(0.0f, 1.0f, 0.25f), WP_TRANSFER_GAMMA, 2.0f), glm::vec3(0.0f, 1.0f, 0.5f));
  glm::vec3 c(0.001f, 0.2f, 0.9f);
  EXPECT_EQ(gpu::encodeTransfer(c, WP_TRANSFER_SRGB, WP_DEFAULT_GAMMA), gpu::linearToSrgb3(c));
}

TEST(PackDisplay, ClampAndSrgbMatchPackSrgba8) {
  for (float r = -0.5f; r < 3.0f; r += 0.0137f) {
    glm::vec3 radiance(r, 0.5f * r, r * r);
    ASSERT_EQ(gpu::packDisplay(radiance, 0.8f, WP_TONE_CLAMP, WP_TRANSFER_SRGB, WP_DEFAULT_GAMMA),
              gpu::packSrgba8(radiance * 0.8f))
        << r;
  }
}

TEST(PackDisplay, ToneCurveAndGammaBytes) {
  // Reinhard of 1 is 0.5, gamma 2 makes it sqrt(0.5) = 0.7071, 180.3 rounds to 180; NaN is 0.
  uint32_t packed = gpu::packDisplay(glm::vec3(2.0f, 0.0f, std::nanf("")), 0.5f, WP_TONE_REINHARD,
                                     WP_TRANSFER_GAMMA, 2.0f);
  EXPECT_EQ(packed, 180u | (0u << 8) | (0u << 16) | (255u << 24));
}

// ---- Thin lens -----------------------------------------------------------------------------

TEST(ThinLens, FilmIsTheSensorCroppedToTheImage) {
  glm::vec2 sensor(WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT);
  glm::vec2 wide = gpu::filmHalfExtent(sensor, 16.0f / 9.0f);
  EXPECT_FLOAT_EQ(wide.x, 0.018f);
  EXPECT_FLOAT_EQ(wide.y, 0.018f * 9.0f / 16.0f);
  glm::vec2 square = gpu::filmHalfExtent(sensor, 1.0f);
  EXPECT_FLOAT_EQ(square.x, 0.012f);
  EXPECT_FLOAT_EQ(square.y, 0.012f);
  glm::vec2 native = gpu::filmHalfExtent(sensor, 1.5f);
  EXPECT_FLOAT_EQ(native.x, 0.018f);
  EXPECT_FLOAT_EQ(native.y, 0.012f);
}

TEST(ThinLens, ThinLensEquation) {
  for (float f : {0.024f, 0.05f, 0.2f})
    for (float d : {0.3f, 1.0f, 10.0f, 1e4f}) {
      float v = gpu::imageDistance(f, d);
      EXPECT_NEAR(1.0 / d + 1.0 / v, 1.0 / f, 1e-5 / f) << f << " " << d;
    }
}

TEST(ThinLens, FieldOfViewAtInfinityFocus) {
  // The top edge of the film sees yfov / 2 off the axis when focused (nearly) at infinity.
  glm::vec2 film = gpu::filmHalfExtent({WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT}, 1.5f);
  float yfov = 0.7f;
  float f = gpu::focalLengthForFieldOfView(yfov, film.y);
  gpu::ThinLens lens = gpu::makeThinLens({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, film, f, 2.8f, 1e7f);
  gpu::CameraRay top = gpu::thinLensRay(lens, {150.0f, 0.0f}, 300u, 200u, {0.0f, 0.0f});
  EXPECT_NEAR(std::acos(-top.direction.z), 0.5 * yfov, 1e-5);
  EXPECT_GT(top.direction.y, 0.0f);  // the top of the image looks up
}

TEST(ThinLens, PinholeLimitMatchesPinholeCamera) {
  glm::vec3 position(1, 2, 3), forward = glm::normalize(glm::vec3(0.3f, -0.2f, -1.0f));
  glm::vec2 film = gpu::filmHalfExtent({WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT}, 640.0f / 480.0f);
  gpu::ThinLens lens = gpu::makeThinLens(position, forward, {0, 1, 0}, film, 0.035f, 4.0f, 2.5f);
  lens.aperture.x = 0.0f;
  float v = gpu::imageDistance(0.035f, 2.5f);
  glm::vec3 right = glm::vec3(lens.right) * (film.x / v), up = glm::vec3(lens.up) * (film.y / v);
  TestRandom random(7);
  for (int i = 0; i < 1000; ++i) {
    glm::vec2 pixel(640.0f * random.next(), 480.0f * random.next());
    gpu::CameraRay ray = gpu::sampleThinLensRay(lens, pixel, 640u, 480u, {random.next(), random.next()});
    // A pinhole camera's ray through the film point, with the film at distance 1.
    glm::vec2 ndc(2.0f * pixel.x / 640.0f - 1.0f, 1.0f - 2.0f * pixel.y / 480.0f);
    glm::vec3 expected = glm::normalize(forward + right * ndc.x + up * ndc.y);
    ASSERT_LT(glm::length(ray.direction - expected), 1e-6f) << i;
    ASSERT_EQ(ray.origin, position);
  }
}

// Where `ray` crosses the plane at `depth` along the lens axis, in double.
glm::dvec3 pointAtDepth(const gpu::ThinLens& lens, const gpu::CameraRay& ray, double depth) {
  glm::dvec3 axis(lens.forward), origin(ray.origin), dir(ray.direction), centre(lens.position);
  double t = (depth - glm::dot(origin - centre, axis)) / glm::dot(dir, axis);
  return origin + dir * t;
}

TEST(ThinLens, EveryApertureSampleMeetsAtTheFocusPoint) {
  glm::vec2 film = gpu::filmHalfExtent({WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT}, 1.5f);
  gpu::ThinLens round = gpu::makeThinLens({0.5f, 1.0f, 4.0f}, glm::normalize(glm::vec3(-0.2f, 0.1f, -1.0f)),
                                          {0, 1, 0}, film, 0.05f, 1.4f, 3.0f);
  gpu::ThinLens hexagon = gpu::withBladedAperture(round, 6u, 0.3f);
  TestRandom random(11);
  for (const gpu::ThinLens& lens : {round, hexagon})
    for (int p = 0; p < 50; ++p) {
      glm::vec2 pixel(300.0f * random.next(), 200.0f * random.next());
      glm::dvec3 focus = pointAtDepth(lens, gpu::thinLensRay(lens, pixel, 300u, 200u, {0, 0}), 3.0);
      for (int s = 0; s < 50; ++s) {
        gpu::CameraRay ray = gpu::sampleThinLensRay(lens, pixel, 300u, 200u, {random.next(), random.next()});
        ASSERT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
        // 1e-6 of the focus distance: float rounding, far below a pixel's footprint there.
        ASSERT_LT(glm::length(pointAtDepth(lens, ray, 3.0) - focus), 3e-6) << p << " " << s;
      }
    }
}

TEST(ThinLens, CircleOfConfusionAtKnownValues) {
  // 50 mm at f/2 (A = 25 mm) focused at 2 m: a point at 4 m blurs to
  // 0.025 * 2 / 4 * 0.05 / 1.95 = 0.3205 mm, one at 1 m to twice that.
  EXPECT_NEAR(gpu::circleOfConfusion(0.025f, 0.05f, 2.0f, 4.0f), 0.025 * 0.5 * 0.05 / 1.95, 1e-9);
  EXPECT_NEAR(gpu::circleOfConfusion(0.025f, 0.05f, 2.0f, 1.0f), 0.025 * 1.0 * 0.05 / 1.95, 1e-9);
  EXPECT_EQ(gpu::circleOfConfusion(0.025f, 0.05f, 2.0f, 2.0f), 0.0f);
  // Far away the blur tends to A f / (S1 - f), the image of the aperture at infinity.
  EXPECT_NEAR(gpu::circleOfConfusion(0.025f, 0.05f, 2.0f, 1e9f), 0.025 * 0.05 / 1.95, 1e-9);
}

// The film position, in metres from the film centre along (right, up), whose ray through
// `lensOffset` passes through `point`. The point where a ray of film position x meets the
// plane through `point` is affine in x, so a secant step solves it; a second polishes it.
glm::dvec2 filmPointSeeing(const gpu::ThinLens& lens, glm::dvec3 point, glm::vec2 lensOffset) {
  const uint32_t width = 3000, height = 2000;
  double depth = glm::dot(point - glm::dvec3(lens.position), glm::dvec3(lens.forward));
  glm::dvec3 right(lens.right), up(lens.up);
  auto miss = [&](glm::dvec2 pixel) {
    gpu::CameraRay ray = gpu::thinLensRay(lens, glm::vec2(pixel), width, height, lensOffset);
    glm::dvec3 d = pointAtDepth(lens, ray, depth) - point;
    return glm::dvec2(glm::dot(d, right), glm::dot(d, up));
  };
  glm::dvec2 pixel(0.5 * width, 0.5 * height);
  for (int iteration = 0; iteration < 2; ++iteration) {
    glm::dvec2 m = miss(pixel), mx = miss(pixel + glm::dvec2(10, 0)), my = miss(pixel + glm::dvec2(0, 10));
    glm::dmat2 jacobian((mx - m) / 10.0, (my - m) / 10.0);
    pixel -= glm::inverse(jacobian) * m;
  }
  return {(2.0 * pixel.x / width - 1.0) * lens.right.w, (1.0 - 2.0 * pixel.y / height) * lens.up.w};
}

TEST(ThinLens, OffFocusPointBlursToTheCircleOfConfusion) {
  // The film points that see a point through the rim of the aperture form its blur disc.
  // Its measured diameter must match circleOfConfusion within 0.1%, or 10 nm on the film
  // (1/1000 of a pixel at 3000 pixels across 36 mm) for the point in focus: the float rays'
  // error, as the formula is exact for a thin lens. A bladed aperture's corners reach the
  // same rim.
  const float f = 0.05f, n = 2.0f, focus = 2.0f;
  glm::vec2 film = gpu::filmHalfExtent({WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT}, 1.5f);
  gpu::ThinLens lens = gpu::makeThinLens({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, film, f, n, focus);
  float radius = lens.aperture.x;
  struct Case {
    glm::dvec3 point;
    double depth;
  };
  for (Case c : {Case{{0, 0, -4}, 4.0}, Case{{0.6, -0.3, -4}, 4.0}, Case{{0, 0, -1}, 1.0}, Case{{-0.1, 0.1, -0.7}, 0.7},
                 Case{{0.3, 0.2, -2}, 2.0}}) {
    double expected = gpu::circleOfConfusion(2.0f * radius, f, focus, float(c.depth));
    glm::dvec2 centre = filmPointSeeing(lens, c.point, {0.0f, 0.0f});
    double widest = 0.0;
    std::vector<glm::dvec2> rim;
    for (int k = 0; k < 72; ++k) {
      double a = 2.0 * kPi * k / 72.0;
      rim.push_back(filmPointSeeing(lens, c.point, glm::vec2(radius * std::cos(a), radius * std::sin(a))));
      EXPECT_NEAR(glm::length(rim.back() - centre), 0.5 * expected, 1e-3 * expected + 1e-8) << c.depth << " " << k;
    }
    for (int k = 0; k < 36; ++k) widest = std::max(widest, glm::length(rim[k] - rim[k + 36]));
    EXPECT_NEAR(widest, expected, 1e-3 * expected + 1e-8) << "depth " << c.depth;
    for (int corner = 0; corner < 6; ++corner) {
      double a = 0.3 + 2.0 * kPi * corner / 6.0;
      glm::dvec2 p = filmPointSeeing(lens, c.point, glm::vec2(radius * std::cos(a), radius * std::sin(a)));
      EXPECT_NEAR(glm::length(p - centre), 0.5 * expected, 1e-3 * expected + 1e-8);
    }
  }
}

// ---- Aperture sampling ---------------------------------------------------------------------

// A convex aperture shape: the interval of y it covers on the vertical line at x.
using Chord = std::function<std::pair<double, double>(double)>;

std::pair<double, double> diskChord(double x) {
  double h = std::sqrt(std::max(0.0, 1.0 - x * x));
  return {-h, h};
}

// The regular polygon of sampleRegularPolygon: inside every edge's half-plane n . p <= cos(pi / sides).
Chord polygonChord(int sides, double rotation) {
  return [=](double x) {
    double lo = -2.0, hi = 2.0, apothem = std::cos(kPi / sides);
    for (int k = 0; k < sides; ++k) {
      double a = rotation + (k + 0.5) * 2.0 * kPi / sides, nx = std::cos(a), ny = std::sin(a);
      double rest = apothem - nx * x;
      if (std::fabs(ny) < 1e-12) {
        if (rest < 0.0) return std::pair<double, double>(0.0, 0.0);
      } else if (ny > 0.0) {
        hi = std::min(hi, rest / ny);
      } else {
        lo = std::max(lo, rest / ny);
      }
    }
    return hi > lo ? std::pair<double, double>(lo, hi) : std::pair<double, double>(0.0, 0.0);
  };
}

// Expected counts on a bins x bins grid over [-1, 1]^2 for `samples` points uniform over the
// shape of area `area`: each cell's overlap, integrated over x by the midpoint rule (fine
// enough that its error is far below the counts' noise).
std::vector<double> expectedGridCounts(const Chord& chord, double area, int bins, double samples) {
  std::vector<double> counts(bins * bins, 0.0);
  double cell = 2.0 / bins;
  const int steps = 2000;
  for (int column = 0; column < bins; ++column)
    for (int s = 0; s < steps; ++s) {
      double x = -1.0 + (column + (s + 0.5) / steps) * cell;
      auto [lo, hi] = chord(x);
      for (int row = 0; row < bins; ++row) {
        double y0 = -1.0 + row * cell, y1 = y0 + cell;
        double overlap = std::max(0.0, std::min(hi, y1) - std::max(lo, y0));
        counts[row * bins + column] += samples * overlap * (cell / steps) / area;
      }
    }
  return counts;
}

void expectUniformOver(const std::function<glm::vec2(glm::vec2)>& sampler, const Chord& chord, double area,
                       uint64_t seed) {
  const int bins = 20, samples = 1000000;
  const double alpha = wp::test::sidakAlpha(0.01, 2);
  std::vector<double> observed(bins * bins, 0.0);
  TestRandom random(seed);
  for (int i = 0; i < samples; ++i) {
    float a = random.next();
    glm::vec2 p = sampler({a, random.next()});
    auto [lo, hi] = chord(p.x);
    ASSERT_TRUE(p.y >= lo - 1e-6 && p.y <= hi + 1e-6) << "outside the aperture: " << p.x << ", " << p.y;
    int column = std::clamp(int((p.x + 1.0f) * 0.5f * bins), 0, bins - 1);
    int row = std::clamp(int((p.y + 1.0f) * 0.5f * bins), 0, bins - 1);
    observed[row * bins + column] += 1.0;
  }
  auto expected = expectedGridCounts(chord, area, bins, samples);
  double total = 0;
  for (double e : expected) total += e;
  EXPECT_NEAR(total, samples, 1e-4 * samples);  // the overlaps tile the shape
  auto result = chiSquareTest(observed, expected);
  EXPECT_TRUE(result.accepts(alpha)) << result.describe();
}

TEST(ApertureSampling, ConcentricDiskIsUniform) {
  expectUniformOver([](glm::vec2 u) { return gpu::sampleConcentricDisk(u); }, diskChord, kPi, 3);
  EXPECT_EQ(gpu::sampleConcentricDisk({0.5f, 0.5f}), glm::vec2(0.0f));
}

TEST(ApertureSampling, HexagonIsUniform) {
  const double rotation = 0.3;
  expectUniformOver([&](glm::vec2 u) { return gpu::sampleRegularPolygon(u, 6u, float(rotation)); },
                    polygonChord(6, rotation), 3.0 * std::sin(2.0 * kPi / 6.0), 5);
}

TEST(ApertureSampling, ApertureScalesToTheLensRadius) {
  glm::vec2 film = gpu::filmHalfExtent({WP_SENSOR_WIDTH, WP_SENSOR_HEIGHT}, 1.5f);
  gpu::ThinLens lens = gpu::makeThinLens({0, 0, 0}, {0, 0, -1}, {0, 1, 0}, film, 0.05f, 2.0f, 3.0f);
  EXPECT_FLOAT_EQ(lens.aperture.x, 0.0125f);  // f / (2 N)
  gpu::ThinLens pentagon = gpu::withBladedAperture(lens, 5u, 0.0f);
  TestRandom random(13);
  float widestRound = 0.0f, widestPentagon = 0.0f;
  for (int i = 0; i < 100000; ++i) {
    glm::vec2 u(random.next(), random.next());
    widestRound = std::max(widestRound, glm::length(gpu::sampleAperture(lens, u)));
    widestPentagon = std::max(widestPentagon, glm::length(gpu::sampleAperture(pentagon, u)));
  }
  EXPECT_LE(widestRound, 0.0125f * (1.0f + 1e-6f));
  EXPECT_GT(widestRound, 0.0125f * 0.99f);
  EXPECT_LE(widestPentagon, 0.0125f * (1.0f + 1e-6f));
  // Two blades cannot make a polygon: fewer than three means the round aperture.
  EXPECT_EQ(gpu::sampleAperture(gpu::withBladedAperture(lens, 2u, 0.0f), {0.3f, 0.8f}),
            gpu::sampleAperture(lens, {0.3f, 0.8f}));
}

}  // namespace
