// Tests of the HDR sky: the lat-long frame and rotation, nearest-texel lookup, chi-square of
// its luminance importance sampling against its pdf, and loading .hdr and .exr files.
#include "shaders/common/environment.h"

#include <gtest/gtest.h>
#include <stb_image_write.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/error.h"
#include "image/image_io.h"
#include "scene/environment_map.h"
#include "support/chi_square.h"

namespace fs = std::filesystem;

namespace {

namespace gpu = wp::gpu;
using wp::test::chiSquareTest;
using wp::test::SphereBinning;
using wp::test::TestRandom;

constexpr double kPi = 3.14159265358979323846;

// The sizes std140/std430 and OpenCL give the struct and the radiance texels.
static_assert(sizeof(gpu::GpuEnvironment) == 32);
static_assert(sizeof(wp::EnvironmentMap::radiance[0]) == 16);

// The three chi-square tests below, each at the Šidák-corrected level so that a correct
// sampler fails the suite with probability 1% (fixed seeds make it deterministic).
const double kAlpha = wp::test::sidakAlpha(0.01, 3);
constexpr int kSamples = 1000000;

// A map and the settings it is seen with; pointers to its arrays stand in for the buffers.
struct Sky {
  wp::EnvironmentMap map;
  gpu::GpuEnvironment env;

  gpu::DeviceBuffers buffers() const {
    gpu::DeviceBuffers b{};
    b.skyRadiance = map.radiance.data();
    b.skyMarginal = map.marginalCdf.data();
    b.skyConditional = map.conditionalCdf.data();
    return b;
  }
  glm::vec3 radiance(glm::vec3 d) const { return gpu::environmentRadiance(buffers(), env, d); }
  float pdf(glm::vec3 d) const { return gpu::environmentPdf(buffers(), env, d); }
  gpu::LightSample sample(glm::vec2 u) const { return gpu::sampleEnvironment(buffers(), env, u); }
  glm::vec3 texelCentre(uint32_t x, uint32_t y) const {
    return gpu::environmentDirection(env, {(x + 0.5f) / map.width, (y + 0.5f) / map.height});
  }
};

Sky makeSky(uint32_t width, uint32_t height, const std::function<glm::vec3(uint32_t, uint32_t)>& texel,
            float intensity = 1.0f, float rotation = 0.0f) {
  std::vector<glm::vec3> radiance;
  for (uint32_t y = 0; y < height; ++y)
    for (uint32_t x = 0; x < width; ++x) radiance.push_back(texel(x, y));
  Sky sky{wp::makeEnvironmentMap(width, height, radiance), gpu::makeEnvironment(width, height, intensity, rotation)};
  return sky;
}

// A smooth sky: brighter and bluer upwards, with a gentle variation around the horizon.
glm::vec3 gradientTexel(uint32_t x, uint32_t y) {
  float u = (x + 0.5f) / 64.0f, v = (y + 0.5f) / 32.0f;
  return {0.2f + 0.6f * (1.0f - v), 0.3f + 0.5f * (1.0f - v) + 0.2f * u, 1.0f + 2.0f * std::sin(3.0f * u) * (1.0f - v)};
}

// The gradient with a tiny sun: three texels 1e5 times brighter, which send 99.6% of the power.
glm::vec3 sunTexel(uint32_t x, uint32_t y) {
  bool sun = (y == 9 && (x == 40 || x == 41)) || (y == 10 && x == 40);
  return gradientTexel(x, y) * (sun ? 1e5f : 1.0f);
}

Sky gradientSky() { return makeSky(64, 32, gradientTexel); }
Sky sunSky() { return makeSky(64, 32, sunTexel); }
Sky rotatedSky() { return makeSky(64, 32, sunTexel, 2.5f, 1.0f); }

// ---- Frame and lookup ----------------------------------------------------------------------

TEST(EnvironmentFrame, DocumentedDirections) {
  gpu::GpuEnvironment env = gpu::makeEnvironment(8, 4, 1.0f, 0.0f);
  auto uvOf = [&](glm::vec3 d) { return gpu::environmentUv(env, d); };
  EXPECT_NEAR(uvOf({0, 0, -1}).x, 0.5f, 1e-6f);  // the default camera's view: the middle
  EXPECT_NEAR(uvOf({0, 0, -1}).y, 0.5f, 1e-6f);
  EXPECT_NEAR(uvOf({1, 0, 0}).x, 0.75f, 1e-6f);  // its right
  EXPECT_NEAR(uvOf({-1, 0, 0}).x, 0.25f, 1e-6f);
  float behind = uvOf({0, 0, 1}).x;
  EXPECT_TRUE(behind < 1e-6f || behind > 1.0f - 1e-6f) << behind;
  EXPECT_NEAR(uvOf({0, 1, 0}).y, 0.0f, 1e-6f);  // zenith: top row
  EXPECT_NEAR(uvOf({0, -1, 0}).y, 1.0f, 1e-6f);
  // Rotating by a quarter turn takes the middle of the map to -x and +x to -z.
  gpu::GpuEnvironment turned = gpu::makeEnvironment(8, 4, 1.0f, float(0.5 * kPi));
  EXPECT_NEAR(gpu::environmentUv(turned, {-1, 0, 0}).x, 0.5f, 1e-6f);
  EXPECT_NEAR(gpu::environmentUv(turned, {0, 0, -1}).x, 0.75f, 1e-6f);
}

TEST(EnvironmentFrame, DirectionAndUvRoundTrip) {
  TestRandom random(21);
  for (float rotation : {0.0f, 1.0f, -2.5f}) {
    gpu::GpuEnvironment env = gpu::makeEnvironment(8, 4, 1.0f, rotation);
    for (int i = 0; i < 10000; ++i) {
      glm::vec2 uv(random.next(), 0.001f + 0.998f * random.next());
      glm::vec3 d = gpu::environmentDirection(env, uv);
      ASSERT_NEAR(glm::length(d), 1.0f, 1e-6f);
      glm::vec2 back = gpu::environmentUv(env, d);
      float du = std::fabs(back.x - uv.x);
      ASSERT_LT(std::min(du, 1.0f - du), 2e-6f) << uv.x << " " << uv.y << " " << rotation;
      ASSERT_NEAR(back.y, uv.y, 2e-6f);
    }
  }
}

TEST(EnvironmentLookup, EvalMatchesTheTexel) {
  for (const Sky& sky : {gradientSky(), sunSky(), rotatedSky()})
    for (uint32_t y = 0; y < sky.map.height; ++y)
      for (uint32_t x = 0; x < sky.map.width; ++x) {
        glm::vec3 expected = glm::vec3(sky.map.radiance[y * sky.map.width + x]) * sky.env.intensity;
        ASSERT_EQ(sky.radiance(sky.texelCentre(x, y)), expected) << x << " " << y;
      }
}

TEST(EnvironmentLookup, RotationTurnsTheSkyAboutY) {
  // What the unrotated sky shows at m appears at Ry(rotation) m.
  Sky plain = sunSky();
  Sky turned = makeSky(64, 32, sunTexel, 1.0f, 1.0f);
  TestRandom random(23);
  int agree = 0;
  for (int i = 0; i < 10000; ++i) {
    glm::vec3 m = gpu::environmentDirection(plain.env, {random.next(), random.next()});
    float c = std::cos(1.0f), s = std::sin(1.0f);
    glm::vec3 world(m.x * c + m.z * s, m.y, -m.x * s + m.z * c);
    agree += plain.radiance(m) == turned.radiance(world);
  }
  EXPECT_GT(agree, 9990);  // all but directions within rounding of a texel edge
}

// ---- Sampling ------------------------------------------------------------------------------

// Sum over texels of the pdf at the texel centre times the texel's (u, v) area times the
// Jacobian: the pdf is constant in (u, v) over a texel, so this is its exact integral.
double pdfIntegral(const Sky& sky) {
  double sum = 0.0;
  for (uint32_t y = 0; y < sky.map.height; ++y)
    for (uint32_t x = 0; x < sky.map.width; ++x) {
      double sinTheta = std::sin(kPi * (y + 0.5) / sky.map.height);
      sum += sky.pdf(sky.texelCentre(x, y)) * 2.0 * kPi * kPi * sinTheta / (sky.map.width * sky.map.height);
    }
  return sum;
}

TEST(EnvironmentSampling, PdfIntegratesToOne) {
  for (const Sky& sky : {gradientSky(), sunSky(), rotatedSky()}) {
    EXPECT_NEAR(pdfIntegral(sky), 1.0, 1e-5);
    // The same by the chi-square's numerical integration over the sphere.
    auto cells = SphereBinning(8, 16, {0, 1, 0}).expectedCounts(
        [&](glm::dvec3 d) { return double(sky.pdf(glm::vec3(d))); }, 1.0, 32);
    double total = 0.0;
    for (double c : cells) total += c;
    EXPECT_NEAR(total, 1.0, 2e-3);
  }
}

TEST(EnvironmentSampling, DensityFollowsLuminanceTimesSinTheta) {
  // The (u, v) density of a texel is its luminance * sin(theta) over the map's mean of that.
  Sky sky = sunSky();
  double mean = 0.0;
  std::vector<double> weight;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      weight.push_back(gpu::luminance(sunTexel(x, y)) * std::sin(kPi * (y + 0.5) / 32.0));
      mean += weight.back() / (64.0 * 32.0);
    }
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      double uvPdf = gpu::environmentUvPdf(sky.buffers(), sky.env, y * 64 + x);
      // Float CDFs near 1 resolve probabilities to ~1e-7 absolute.
      ASSERT_NEAR(uvPdf, weight[y * 64 + x] / mean, 1e-4 * weight[y * 64 + x] / mean + 2e-4) << x << " " << y;
    }
}

void expectSamplesFollowPdf(const Sky& sky, uint64_t seed) {
  std::vector<glm::dvec3> directions;
  directions.reserve(kSamples);
  TestRandom random(seed);
  int pdfMismatches = 0, radianceMismatches = 0;
  for (int i = 0; i < kSamples; ++i) {
    float a = random.next();
    gpu::LightSample s = sky.sample({a, random.next()});
    ASSERT_GT(s.pdf, 0.0f);
    ASSERT_NEAR(glm::length(s.direction), 1.0f, 1e-5f);
    ASSERT_EQ(s.distance, WP_FLT_MAX);
    // The returned pdf and radiance are those of the texel chosen; evaluating at the
    // direction finds the same texel except within float rounding of its edge.
    float evaluated = sky.pdf(s.direction);
    pdfMismatches += std::fabs(evaluated - s.pdf) > 1e-4f * s.pdf;
    radianceMismatches += sky.radiance(s.direction) != s.radiance;
    directions.push_back(s.direction);
  }
  EXPECT_LT(pdfMismatches, kSamples / 10000) << "pdf mismatches";
  EXPECT_LT(radianceMismatches, kSamples / 10000) << "radiance mismatches";
  // Rows of the cells fall between the map's rows of texels, so the adaptive integration
  // meets the density's steps inside cells; 32 points per ring resolve the 64 columns.
  SphereBinning binning(16, 32, {0, 1, 0});
  auto expected = binning.expectedCounts([&](glm::dvec3 d) { return double(sky.pdf(glm::vec3(d))); }, kSamples, 32);
  auto result = chiSquareTest(binning.histogram(directions), expected);
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

TEST(EnvironmentSampling, SmoothGradientFollowsPdf) { expectSamplesFollowPdf(gradientSky(), 31); }

TEST(EnvironmentSampling, TinyBrightSunFollowsPdf) { expectSamplesFollowPdf(sunSky(), 37); }

TEST(EnvironmentSampling, RotatedMapFollowsPdf) { expectSamplesFollowPdf(rotatedSky(), 41); }

TEST(EnvironmentSampling, SunGetsItsShareOfSamples) {
  // Importance sampling must send most samples to the sun: its share of luminance * sin.
  Sky sky = sunSky();
  double sun = 0.0, total = 0.0;
  for (uint32_t y = 0; y < 32; ++y)
    for (uint32_t x = 0; x < 64; ++x) {
      double w = gpu::luminance(sunTexel(x, y)) * std::sin(kPi * (y + 0.5) / 32.0);
      total += w;
      if (sunTexel(x, y) != gradientTexel(x, y)) sun += w;
    }
  TestRandom random(43);
  int hits = 0;
  const int n = kSamples;
  for (int i = 0; i < n; ++i) {
    float a = random.next();
    gpu::LightSample s = sky.sample({a, random.next()});
    hits += s.radiance.x > 1000.0f;
  }
  double share = sun / total;
  EXPECT_GT(share, 0.9);
  // Five standard deviations of the binomial count: the sky's 0.4% share is right to 8%.
  EXPECT_NEAR(double(hits) / n, share, 5.0 * std::sqrt(share * (1.0 - share) / n));
}

TEST(EnvironmentSampling, BlackSkyIsStillSampled) {
  Sky sky = makeSky(16, 8, [](uint32_t, uint32_t) { return glm::vec3(0.0f); });
  EXPECT_EQ(sky.map.luminanceIntegral, 0.0);
  EXPECT_NEAR(pdfIntegral(sky), 1.0, 1e-5);
  gpu::LightSample s = sky.sample({0.3f, 0.6f});
  EXPECT_GT(s.pdf, 0.0f);
  EXPECT_EQ(s.radiance, glm::vec3(0.0f));
}

TEST(EnvironmentMap, LuminanceIntegralAndPower) {
  // A uniform sky of luminance 2 integrates to 2 * 4 pi.
  Sky sky = makeSky(32, 16, [](uint32_t, uint32_t) { return glm::vec3(2.0f); });
  EXPECT_NEAR(sky.map.luminanceIntegral, 8.0 * kPi, 1e-9);
  EXPECT_NEAR(wp::environmentPower(sky.map, 0.5, 3.0), kPi * 9.0 * 0.5 * 8.0 * kPi, 1e-6);
  EXPECT_EQ(sky.map.marginalCdf.size(), 17u);
  EXPECT_EQ(sky.map.conditionalCdf.size(), 16u * 33u);
  EXPECT_EQ(sky.map.marginalCdf.back(), 1.0f);
}

TEST(EnvironmentMap, NegativeClampedNonFiniteRejected) {
  auto map = wp::makeEnvironmentMap(2, 1, {glm::vec3(-1.0f, 2.0f, 3.0f), glm::vec3(1.0f)});
  EXPECT_EQ(map.radiance[0], glm::vec4(0.0f, 2.0f, 3.0f, 0.0f));
  EXPECT_THROW(wp::makeEnvironmentMap(2, 1, {glm::vec3(1.0f), glm::vec3(std::nanf(""))}), wp::Error);
  EXPECT_THROW(wp::makeEnvironmentMap(2, 1, {glm::vec3(INFINITY), glm::vec3(1.0f)}), wp::Error);
}

// ---- Loading -------------------------------------------------------------------------------

// A fresh empty directory per test, removed afterwards.
class EnvironmentLoadTest : public ::testing::Test {
protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir = fs::temp_directory_path() / ("wavepath_environment_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  // The one-line wp::Error message of loading `path`, or "" when it loads.
  static std::string loadError(const fs::path& path) {
    try {
      wp::loadEnvironmentMap(path);
    } catch (const wp::Error& e) {
      return e.what();
    }
    return "";
  }

  fs::path dir;
};

std::vector<float> testPixels(int width, int height) {
  std::vector<float> rgb;
  for (int i = 0; i < width * height; ++i) {
    rgb.push_back(0.25f * (i + 1));
    rgb.push_back(100.0f / (i + 1));
    rgb.push_back(i == 3 ? 5e4f : 0.01f * i);
  }
  return rgb;
}

TEST_F(EnvironmentLoadTest, ReadsRadianceHdr) {
  const int width = 6, height = 3;
  std::vector<float> rgb = testPixels(width, height);
  fs::path path = dir / "sky.HDR";
  ASSERT_TRUE(stbi_write_hdr(path.c_str(), width, height, 3, rgb.data()));
  wp::EnvironmentMap map = wp::loadEnvironmentMap(path);
  ASSERT_EQ(map.width, uint32_t(width));
  ASSERT_EQ(map.height, uint32_t(height));
  for (int i = 0; i < width * height; ++i)
    for (int c = 0; c < 3; ++c) {
      // RGBE keeps 8 bits of mantissa shared by the three channels.
      float expected = rgb[3 * i + c], largest = std::max({rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]});
      EXPECT_NEAR(map.radiance[i][c], expected, largest / 128.0f) << i << " " << c;
    }
  EXPECT_EQ(map.marginalCdf.size(), size_t(height + 1));
}

TEST_F(EnvironmentLoadTest, ReadsOpenExr) {
  const int width = 5, height = 4;
  std::vector<float> rgb = testPixels(width, height);
  wp::RadianceImage image;
  image.width = width;
  image.height = height;
  for (int i = 0; i < width * height; ++i) image.mean.emplace_back(rgb[3 * i], rgb[3 * i + 1], rgb[3 * i + 2]);
  fs::path path = dir / "sky.exr";
  wp::writeImage(path, image);
  wp::EnvironmentMap map = wp::loadEnvironmentMap(path);
  ASSERT_EQ(map.width, uint32_t(width));
  ASSERT_EQ(map.height, uint32_t(height));
  for (int i = 0; i < width * height; ++i) EXPECT_EQ(glm::vec3(map.radiance[i]), image.mean[i]) << i;
}

TEST_F(EnvironmentLoadTest, ErrorsAreOneLineNamingTheFile) {
  fs::path missing = dir / "missing.hdr";
  fs::path text = dir / "notes.hdr";
  std::ofstream(text) << "this is not an image\n";
  fs::path textExr = dir / "notes.exr";
  std::ofstream(textExr) << "this is not an image either\n";
  fs::path png = dir / "sky.png";
  std::ofstream(png) << "whatever";
  // A Radiance header wavepath does not accept (XYZ instead of RGB primaries).
  fs::path xyz = dir / "xyz.hdr";
  std::ofstream(xyz) << "#?RADIANCE\nFORMAT=32-bit_rle_xyze\n\n-Y 4 +X 4\n";
  fs::path folder = dir / "folder.hdr";
  fs::create_directories(folder);
  fs::path nanExr = dir / "nan.exr";
  wp::RadianceImage image;
  image.width = 2;
  image.height = 1;
  image.mean = {glm::vec3(1.0f), glm::vec3(std::nanf(""))};
  wp::writeImage(nanExr, image);

  struct Case {
    fs::path path;
    const char* says;
  };
  for (const Case& c : {Case{missing, "no such file"}, Case{text, "not a Radiance HDR file"},
                        Case{textExr, "not an OpenEXR file"}, Case{png, "unsupported format '.png'"},
                        Case{xyz, "not 32-bit_rle_rgbe"}, Case{nanExr, "texel (1, 0) is not a finite number"},
                        Case{folder, "is a directory"}}) {
    std::string message = loadError(c.path);
    EXPECT_NE(message.find(c.path.string()), std::string::npos) << c.path << ": " << message;
    EXPECT_NE(message.find(c.says), std::string::npos) << message;
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
  }
}

TEST(EnvironmentAsset, ShippedSkyLoads) {
  const char* source = std::getenv("WAVEPATH_SOURCE_DIR");
  ASSERT_NE(source, nullptr) << "WAVEPATH_SOURCE_DIR is not set; run the tests through ctest";
  wp::EnvironmentMap map = wp::loadEnvironmentMap(fs::path(source) / "assets" / "sky.hdr");
  EXPECT_EQ(map.width, 512u);
  EXPECT_EQ(map.height, 256u);
  // A clear day: the sun is some 1e5 times brighter than the sky around it and sends most
  // of the light, while the zenith sky is a few thousand cd/m^2.
  std::vector<double> lum;
  for (const glm::vec4& t : map.radiance) lum.push_back(gpu::luminance(glm::vec3(t)));
  double brightest = *std::max_element(lum.begin(), lum.end());
  double zenith = lum[map.width / 2];
  EXPECT_GT(brightest / zenith, 1e4);
  EXPECT_GT(zenith, 1000.0);
  EXPECT_LT(zenith, 20000.0);
}

}  // namespace
