// Tests of the portable BSDF library (fresnel.h, microfacet.h, bsdf_models.h, material.h):
// chi-square fits of every sampler against its pdf, energy, reciprocity, the agreement of
// sample, eval and pdf, delta lobes, Fresnel and Beer's law.
#include "shaders/common/material.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

// The integrator's material dispatch, with Lambert as the reference of albedo exactly 1.
#include "shaders/common/bsdf.h"
#include "support/chi_square.h"

namespace {

namespace gpu = wp::gpu;
using wp::test::chiSquareTest;
using wp::test::SphereBinning;
using wp::test::TestRandom;

constexpr double kPi = 3.14159265358979323846;
constexpr int kChiSquareSamples = 200000;
// Cells of the sphere binning, and points per cell edge of its integration: the lobes are
// binned about their centres, so this resolves them; finer grids cost seconds.
constexpr int kCosThetaBins = 16;
constexpr int kPhiBins = 32;
constexpr int kResolution = 8;

// Perceptual roughness values of the sampling tests; alpha = r^2 is 0.05, 0.2, 0.5, 1.
const float kRoughness[] = {0.22f, 0.45f, 0.71f, 1.0f};
const float kAlphas[] = {0.0625f, 0.2f, 0.5f, 1.0f};
// cos(theta_o) of the sampling and energy tests: near normal, oblique, grazing.
const float kCosines[] = {0.9f, 0.5f, 0.1f};

gpu::SurfaceMaterial makeMaterial(glm::vec3 baseColor, float metallic, float roughness, float ior,
                                  float transmission) {
  gpu::SurfaceMaterial m;
  m.baseColor = baseColor;
  m.metallic = metallic;
  m.roughness = roughness;
  m.ior = ior;
  m.transmission = transmission;
  m.disneyDiffuse = false;
  return gpu::withDefaultExtensions(m);
}

gpu::SurfaceMaterial metal(float roughness, glm::vec3 f0 = glm::vec3(0.95f, 0.64f, 0.54f)) {
  return makeMaterial(f0, 1.0f, roughness, 1.5f, 0.0f);
}
gpu::SurfaceMaterial plastic(float roughness, glm::vec3 albedo = glm::vec3(0.5f, 0.4f, 0.3f)) {
  return makeMaterial(albedo, 0.0f, roughness, 1.5f, 0.0f);
}
gpu::SurfaceMaterial glass(float roughness, glm::vec3 tint = glm::vec3(1.0f)) {
  return makeMaterial(tint, 0.0f, roughness, 1.5f, 1.0f);
}
// The seed report's model: plastic over normalized Disney diffuse ("diffuse": "disney").
gpu::SurfaceMaterial disneyPlastic(float roughness, glm::vec3 albedo = glm::vec3(0.5f, 0.4f, 0.3f)) {
  gpu::SurfaceMaterial m = plastic(roughness, albedo);
  m.disneyDiffuse = true;
  return m;
}
// The extensions' layers (KHR_materials_sheen, _clearcoat) over a base, and
// KHR_materials_specular's tinted, weakened specular layer on plastic.
gpu::SurfaceMaterial sheened(gpu::SurfaceMaterial m, glm::vec3 color = glm::vec3(0.9f, 0.7f, 0.5f), float roughness = 0.5f) {
  m.sheenColor = color;
  m.sheenRoughness = roughness;
  return m;
}
gpu::SurfaceMaterial coated(gpu::SurfaceMaterial m, float roughness, glm::vec3 normal = glm::vec3(0.0f, 0.0f, 1.0f)) {
  m.clearcoat = 1.0f;
  m.clearcoatRoughness = roughness;
  m.clearcoatNormal = glm::normalize(normal);
  return m;
}
gpu::SurfaceMaterial specular(gpu::SurfaceMaterial m, glm::vec3 color, float weight) {
  m.specularColor = color;
  m.specularWeight = weight;
  return m;
}
// Every lobe at once: half metal, and of the rest half glass, half plastic.
gpu::SurfaceMaterial mixed(float roughness, glm::vec3 base = glm::vec3(0.8f, 0.6f, 0.4f)) {
  return makeMaterial(base, 0.5f, roughness, 1.5f, 0.5f);
}

// wo at cos(theta) = cosTheta (negative: below the surface), azimuth 0.3 rad.
glm::vec3 outgoing(float cosTheta) {
  float sinTheta = std::sqrt(std::max(0.0f, 1.0f - cosTheta * cosTheta));
  return {sinTheta * std::cos(0.3f), sinTheta * std::sin(0.3f), cosTheta};
}

glm::vec3 uniformSphere(TestRandom& random) {
  float z = 1.0f - 2.0f * random.next();
  float r = std::sqrt(std::max(0.0f, 1.0f - z * z)), phi = float(2.0 * kPi) * random.next();
  return {r * std::cos(phi), r * std::sin(phi), z};
}

glm::vec3 next3(TestRandom& random) {
  float x = random.next(), y = random.next();
  return {x, y, random.next()};
}

bool allFinite(glm::vec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// ---- Chi-square goodness of fit ---------------------------------------------------------

struct SamplerCase {
  std::string name;
  gpu::SurfaceMaterial material;
  float cosThetaO;  // negative: from below the surface (inside glass)
  uint32_t flags;
  uint64_t seed = 0;  // set from the case's position in the list
};

// gtest prints parameters as bytes unless told otherwise.
void PrintTo(const SamplerCase& c, std::ostream* out) { *out << c.name; }

std::string caseName(const char* lobe, float roughness, float cosThetaO) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "%s_r%03d_cos%s%02d", lobe, int(std::lround(roughness * 100)),
                cosThetaO < 0.0f ? "Minus" : "", int(std::lround(std::fabs(cosThetaO) * 10)));
  return buffer;
}

std::vector<SamplerCase> samplerCases() {
  std::vector<SamplerCase> cases;
  for (float r : kRoughness)
    for (float c : kCosines) {
      cases.push_back({caseName("Metal", r, c), metal(r), c, 0u});
      cases.push_back({caseName("Plastic", r, c), plastic(r), c, 0u});
      cases.push_back({caseName("Glass", r, c), glass(r), c, 0u});
      cases.push_back({caseName("Glass", r, -c), glass(r), -c, 0u});
    }
  for (float c : kCosines) cases.push_back({caseName("GlassWidened", 0.5f, c), glass(0.5f), c, WP_BSDF_WIDEN_BECKMANN});
  cases.push_back({caseName("GlassWidened", 0.5f, -0.5f), glass(0.5f), -0.5f, WP_BSDF_WIDEN_BECKMANN});
  for (float c : kCosines) {
    cases.push_back({caseName("PlasticFixedLobeChoice", 0.5f, c), plastic(0.5f), c, WP_BSDF_FIXED_LOBE_CHOICE});
    cases.push_back({caseName("PlasticDisney", 0.71f, c), disneyPlastic(0.71f), c, 0u});
  }
  for (float c : kCosines) cases.push_back({caseName("Mixed", 0.5f, c), mixed(0.5f), c, 0u});
  for (float c : kCosines) {
    cases.push_back({caseName("SheenOverPlastic", 0.71f, c), sheened(plastic(0.71f, glm::vec3(0.3f))), c, 0u});
    cases.push_back({caseName("SheenSharp", 0.45f, c), sheened(plastic(0.45f), glm::vec3(1.0f), 0.1f), c, 0u});
    cases.push_back({caseName("CoatOverMetal", 0.45f, c), coated(metal(0.45f), 0.22f), c, 0u});
    cases.push_back({caseName("TiltedCoat", 0.71f, c), coated(plastic(0.71f), 0.45f, glm::vec3(0.4f, 0.1f, 0.9f)), c, 0u});
    cases.push_back({caseName("TintedSpecular", 0.45f, c),
                     specular(plastic(0.45f), glm::vec3(1.0f, 0.5f, 0.2f), 0.7f), c, 0u});
  }
  cases.push_back({caseName("CoatAndSheenOverGlass", 0.45f, 0.5f), coated(sheened(glass(0.45f)), 0.3f), 0.5f, 0u});
  cases.push_back({caseName("CoatAndSheenOverGlass", 0.45f, -0.5f), coated(sheened(glass(0.45f)), 0.3f), -0.5f, 0u});
  cases.push_back({caseName("Mixed", 0.5f, -0.5f), mixed(0.5f), -0.5f, 0u});
  for (size_t i = 0; i < cases.size(); ++i) cases[i].seed = 1000 + i;
  return cases;
}

const std::vector<SamplerCase> kSamplerCases = samplerCases();

// Every chi-square test in this file: one per sampler case and hemisphere it can scatter
// into, plus GGX's visible normals at each alpha and cosine and Beckmann normals at each alpha. Each runs at the Šidák-corrected
// level, so a correct implementation fails the suite with probability 1% over the choice
// of seeds (which are fixed, so results are deterministic).
int countChiSquareTests() {
  int count = int(std::size(kAlphas) * (std::size(kCosines) + 1));
  for (const SamplerCase& c : kSamplerCases) count += c.material.transmission > 0.0f ? 2 : 1;
  return count;
}
const int kChiSquareTests = countChiSquareTests();
const double kAlpha = wp::test::sidakAlpha(0.01, kChiSquareTests);

// A chi-square test of the samples in one hemisphere (z * side > 0) against the pdf there,
// on cells over the whole sphere about `axis` (the lobe's centre, so rings of constant
// theta follow the lobe even where grazing angles squeeze it into a thin arc). All other
// samples, including failed ones, share one more cell, which expects the sample count
// minus what the pdf puts into the hemisphere. Integrating one hemisphere at a time
// (SphereBinning's support) keeps the density's jump at the horizon exact. Returns
// nothing when the pdf puts less than 1% of the samples there: too few for a test.
std::optional<wp::test::ChiSquareResult> fitHemisphere(const std::vector<glm::dvec3>& directions, int sampleCount,
                                                       const std::function<double(glm::dvec3)>& pdf,
                                                       glm::dvec3 axis, double side) {
  SphereBinning binning(kCosThetaBins, kPhiBins, axis);
  std::vector<glm::dvec3> inside;
  for (glm::dvec3 d : directions)
    if (d.z * side > 0.0) inside.push_back(d);
  auto part = [&](glm::dvec3 d) { return d.z * side > 0.0 ? pdf(d) : 0.0; };
  std::vector<double> expected = binning.expectedCounts(part, sampleCount, kResolution, {{0, 0, side}});
  double covered = 0;
  for (double e : expected) covered += e;
  if (covered < 0.01 * sampleCount) return std::nullopt;
  std::vector<double> observed = binning.histogram(inside);
  observed.push_back(double(sampleCount - inside.size()));
  expected.push_back(std::max(0.0, sampleCount - covered));
  return chiSquareTest(observed, expected);
}

class MaterialSampler : public ::testing::TestWithParam<SamplerCase> {};

TEST_P(MaterialSampler, SamplesFollowPdfMaterial) {
  const SamplerCase& c = GetParam();
  glm::vec3 wo = outgoing(c.cosThetaO);
  TestRandom random(c.seed);
  std::vector<glm::dvec3> directions;
  directions.reserve(kChiSquareSamples);
  int failures = 0, deltas = 0;
  for (int i = 0; i < kChiSquareSamples; ++i) {
    gpu::MaterialSample s = gpu::sampleMaterial(c.material, wo, next3(random), c.flags);
    if (!(s.pdf > 0.0f)) {
      ++failures;
      continue;
    }
    if (s.flags & WP_SAMPLE_DELTA) ++deltas;
    directions.push_back(glm::dvec3(s.wi));
  }
  ASSERT_EQ(deltas, 0);
  auto pdf = [&](glm::dvec3 d) { return double(gpu::pdfMaterial(c.material, wo, glm::vec3(d), c.flags)); };
  float side = c.cosThetaO < 0.0f ? -1.0f : 1.0f;
  auto reflection = fitHemisphere(directions, kChiSquareSamples, pdf, glm::dvec3(-wo.x, -wo.y, wo.z), side);
  ASSERT_TRUE(reflection.has_value());
  EXPECT_TRUE(reflection->accepts(kAlpha)) << "reflection: " << reflection->describe() << ", failed samples "
                                           << failures;
  if (c.material.transmission == 0.0f) return;
  // Transmission is fitted about the direction Snell's law gives for the macro normal.
  float eta = side > 0.0f ? c.material.ior : 1.0f / c.material.ior;
  glm::vec3 o(wo.x, wo.y, wo.z * side);
  gpu::Refraction r = gpu::refractAbout(o, glm::vec3(0, 0, 1), eta);
  glm::dvec3 axis = r.valid ? glm::dvec3(r.direction.x, r.direction.y, r.direction.z * side) : glm::dvec3(0, 0, -side);
  auto transmission = fitHemisphere(directions, kChiSquareSamples, pdf, axis, -side);
  if (transmission) {
    EXPECT_TRUE(transmission->accepts(kAlpha)) << "transmission: " << transmission->describe();
  }
}

INSTANTIATE_TEST_SUITE_P(Materials, MaterialSampler, ::testing::ValuesIn(kSamplerCases),
                         [](const auto& info) { return info.param.name; });

// Microfacet normals: Beckmann's density D(m) cos(theta_m), which must integrate to 1 (the
// projected microfacet area is the macro area), and GGX's visible normals seen from o,
// G1(o) max(0, o.m) D(m) / cos(theta_o), which must integrate to 1 too (the area o sees).
struct NormalCase {
  std::string name;
  float alpha;
  bool beckmann;
  float cosThetaO;  // GGX's visible normals only
  uint64_t seed;
};

void PrintTo(const NormalCase& c, std::ostream* out) { *out << c.name; }

std::vector<NormalCase> normalCases() {
  std::vector<NormalCase> cases;
  for (float a : kAlphas) {
    std::string suffix = "_a" + std::to_string(int(std::lround(a * 1000)));
    for (float c : kCosines) {
      std::string name = "GgxVisible" + suffix + "_cos" + std::to_string(int(std::lround(c * 10)));
      cases.push_back({name, a, false, c, 2000 + cases.size()});
    }
    cases.push_back({"Beckmann" + suffix, a, true, 1.0f, 2000 + cases.size()});
  }
  return cases;
}

glm::vec3 normalCaseOutgoing(const NormalCase& c) { return outgoing(c.cosThetaO); }

double normalPdf(const NormalCase& c, glm::dvec3 m) {
  glm::vec3 n(m);
  if (c.beckmann) return double(gpu::beckmannD(c.alpha, n) * std::max(n.z, 0.0f));
  glm::vec3 o = normalCaseOutgoing(c);
  return double(gpu::ggxG1(c.alpha, o.z) * std::max(glm::dot(o, n), 0.0f) * gpu::ggxD(c.alpha, n) / o.z);
}

class MicrofacetNormals : public ::testing::TestWithParam<NormalCase> {};

TEST_P(MicrofacetNormals, SamplesFollowTheirDensity) {
  const NormalCase& c = GetParam();
  TestRandom random(c.seed);
  std::vector<glm::dvec3> normals;
  for (int i = 0; i < kChiSquareSamples; ++i) {
    glm::vec2 u(random.next(), random.next());
    glm::vec3 m = c.beckmann ? gpu::sampleBeckmannNormal(c.alpha, u)
                             : gpu::sampleGgxVisibleNormal(c.alpha, normalCaseOutgoing(c), u);
    ASSERT_NEAR(glm::length(m), 1.0f, 1e-5f);
    normals.push_back(glm::dvec3(m));
  }
  auto result = fitHemisphere(normals, kChiSquareSamples, [&](glm::dvec3 m) { return normalPdf(c, m); },
                              {0, 0, 1}, 1.0);
  ASSERT_TRUE(result.has_value());
  EXPECT_TRUE(result->accepts(kAlpha)) << result->describe();
}

TEST_P(MicrofacetNormals, DensityIntegratesToOne) {
  const NormalCase& c = GetParam();
  auto cells = SphereBinning(24, 1).expectedCounts([&](glm::dvec3 m) { return normalPdf(c, m); }, 1.0, 16);
  double integral = 0;
  for (double cell : cells) integral += cell;
  EXPECT_NEAR(integral, 1.0, 2e-3);
}

INSTANTIATE_TEST_SUITE_P(Distributions, MicrofacetNormals, ::testing::ValuesIn(normalCases()),
                         [](const auto& info) { return info.param.name; });

// ---- Energy ---------------------------------------------------------------------------

struct Estimate {
  glm::dvec3 mean{0.0}, standardError{0.0};
};

// Mean and standard error of the mean of `count` values drawn by `draw`.
template <typename Draw>
Estimate estimate(int count, Draw draw) {
  glm::dvec3 sum(0.0), sumSquares(0.0);
  for (int i = 0; i < count; ++i) {
    glm::dvec3 v = draw();
    sum += v;
    sumSquares += v * v;
  }
  Estimate e;
  e.mean = sum / double(count);
  e.standardError = glm::sqrt(glm::max(sumSquares / double(count) - e.mean * e.mean, 0.0) / double(count - 1));
  return e;
}

// Refraction scales radiance by 1 / eta^2 (radiance transport); energy is the radiance
// times eta^2 again, eta = n(wi's side) / n(wo's side).
double energyScale(const gpu::SurfaceMaterial& m, glm::vec3 wo, glm::vec3 wi) {
  if (wo.z * wi.z >= 0.0f) return 1.0;
  double eta = wo.z > 0.0f ? m.ior : 1.0 / m.ior;
  return eta * eta;
}

// Directional albedo as the mean of sample weights (delta lobes included).
Estimate sampledAlbedo(const gpu::SurfaceMaterial& m, glm::vec3 wo, uint32_t flags, int count, uint64_t seed) {
  TestRandom random(seed);
  return estimate(count, [&] {
    gpu::MaterialSample s = gpu::sampleMaterial(m, wo, next3(random), flags);
    return s.pdf > 0.0f ? glm::dvec3(s.weight) * energyScale(m, wo, s.wi) : glm::dvec3(0.0);
  });
}

// Directional albedo as the integral of evalMaterial's f |cos| over uniform directions
// (blind to delta lobes).
Estimate integratedAlbedo(const gpu::SurfaceMaterial& m, glm::vec3 wo, int count, uint64_t seed) {
  TestRandom random(seed);
  return estimate(count, [&] {
    glm::vec3 wi = uniformSphere(random);
    return glm::dvec3(gpu::evalMaterial(m, wo, wi, 0u).fCos) * (4.0 * kPi) * energyScale(m, wo, wi);
  });
}

struct EnergyCase {
  const char* name;
  gpu::SurfaceMaterial (*make)(float roughness);
  float side;  // +1: wo above the surface, -1: below
  uint32_t flags;
};

// Every lobe white, so nothing but the model can absorb.
const EnergyCase kEnergyCases[] = {
    {"metal", [](float r) { return metal(r, glm::vec3(1.0f)); }, 1.0f, 0u},
    {"plastic", [](float r) { return plastic(r, glm::vec3(1.0f)); }, 1.0f, 0u},
    {"glass", [](float r) { return glass(r); }, 1.0f, 0u},
    {"glass inside", [](float r) { return glass(r); }, -1.0f, 0u},
    {"glass widened", [](float r) { return glass(r); }, 1.0f, WP_BSDF_WIDEN_BECKMANN},
    {"plastic 50/50", [](float r) { return plastic(r, glm::vec3(1.0f)); }, 1.0f, WP_BSDF_FIXED_LOBE_CHOICE},
    {"mixed", [](float r) { return mixed(r, glm::vec3(1.0f)); }, 1.0f, 0u},
    {"coated metal", [](float r) { return coated(metal(r, glm::vec3(1.0f)), 0.3f); }, 1.0f, 0u},
    {"sheen plastic", [](float r) { return sheened(plastic(r, glm::vec3(1.0f)), glm::vec3(1.0f), r); }, 1.0f, 0u},
    {"coated sheen", [](float r) { return coated(sheened(plastic(r, glm::vec3(1.0f)), glm::vec3(1.0f)), r); }, 1.0f, 0u},
};

// Neither estimate exceeds 1 by more than 3 standard errors, and where both see the whole
// BSDF (no delta lobe) they agree: the sample weights are unbiased for the integral of
// f |cos|, failed samples included. Prints the table of albedos.
TEST(Energy, AlbedoIsAtMostOneAndSamplingAgreesWithIntegration) {
  const float roughnesses[] = {0.0f, 0.3f, 0.5f, 0.7f, 1.0f};
  constexpr int kCount = 50000;
  std::printf("%-14s %5s %5s %9s %9s %9s\n", "material", "r", "cos", "sampled", "integral", "se");
  uint64_t seed = 100;
  for (const EnergyCase& c : kEnergyCases)
    for (float r : roughnesses)
      for (float cosTheta : kCosines) {
        gpu::SurfaceMaterial m = c.make(r);
        glm::vec3 wo = outgoing(cosTheta * c.side);
        Estimate sampled = sampledAlbedo(m, wo, c.flags, kCount, ++seed);
        Estimate integrated = integratedAlbedo(m, wo, kCount, ++seed);
        std::printf("%-14s %5.2f %5.2f %9.5f %9.5f %9.5f\n", c.name, r, cosTheta, sampled.mean.x, integrated.mean.x,
                    integrated.standardError.x);
        for (int k = 0; k < 3; ++k) {
          SCOPED_TRACE(std::string(c.name) + " r " + std::to_string(r) + " cos " + std::to_string(cosTheta));
          EXPECT_LE(sampled.mean[k], 1.0 + 3.0 * sampled.standardError[k] + 1e-6);
          EXPECT_LE(integrated.mean[k], 1.0 + 3.0 * integrated.standardError[k]);
          if (r > 0.0f) {
            double se = std::hypot(sampled.standardError[k], integrated.standardError[k]);
            EXPECT_NEAR(sampled.mean[k], integrated.mean[k], 4.0 * se);
          }
        }
      }
}

// The integrator's Lambert (bsdf.h) with albedo 1 reflects everything, seen from either
// side: each sample's weight is 1, and the integral of f |cos| is 1 within its error.
TEST(Energy, WhiteLambertHasAlbedoOne) {
  gpu::GpuMaterial lambert{};
  lambert.baseColor = glm::vec4(1.0f);
  lambert.info = glm::uvec4(WP_MATERIAL_LAMBERT, 0u, 0u, 0u);
  TestRandom random(7);
  for (float side : {1.0f, -1.0f}) {
    glm::vec3 wo = outgoing(0.5f) * glm::vec3(1.0f, 1.0f, side);
    for (int i = 0; i < 10000; ++i) {
      glm::vec3 u(random.next(), random.next(), random.next());
      gpu::MaterialSample s = gpu::sampleBsdf(lambert, wo, u, 0u);
      ASSERT_GT(s.pdf, 0.0f);
      ASSERT_GT(s.wi.z * side, 0.0f);
      ASSERT_NEAR(s.weight.x, 1.0f, 1e-6f);
      ASSERT_NEAR(gpu::evalBsdf(lambert, wo, s.wi, 0u).pdf, s.pdf, 1e-5f * s.pdf);
    }
    Estimate integrated = estimate(200000, [&] {
      glm::vec3 wi = uniformSphere(random);
      return glm::dvec3(gpu::evalBsdf(lambert, wo, wi, 0u).fCos) * (4.0 * kPi);
    });
    EXPECT_NEAR(integrated.mean.x, 1.0, 3.0 * integrated.standardError.x);
  }
}

// The white furnace of glTF's two opaque materials: a white metal (F0 = 1) and a white
// dielectric (base colour 1, IOR 1.5) reflect everything at every roughness and angle, since
// energy compensation gives back what single-scattering GGX loses (without it a rough white
// metal seen head-on reflects 31%). The tolerance is the tables' interpolation error; the
// sampled albedo has 1% noise at most here. Prints the table.
TEST(Energy, WhiteMetalAndDielectricReflectEverything) {
  const float roughnesses[] = {0.0f, 0.25f, 0.5f, 0.75f, 1.0f};
  const float cosines[] = {1.0f, 0.9f, 0.5f, 0.2f, 0.05f};
  std::printf("%-10s %5s %5s %9s %9s\n", "material", "r", "cos", "sampled", "integral");
  uint64_t seed = 900;
  for (bool isMetal : {true, false})
    for (float r : roughnesses)
      for (float cosTheta : cosines) {
        gpu::SurfaceMaterial m = isMetal ? metal(r, glm::vec3(1.0f)) : plastic(r, glm::vec3(1.0f));
        Estimate sampled = sampledAlbedo(m, outgoing(cosTheta), 0u, 40000, ++seed);
        std::printf("%-10s %5.2f %5.2f %9.5f", isMetal ? "metal" : "dielectric", r, cosTheta, sampled.mean.x);
        SCOPED_TRACE(std::string(isMetal ? "metal" : "dielectric") + " r " + std::to_string(r) + " cos " +
                     std::to_string(cosTheta));
        EXPECT_NEAR(sampled.mean.x, 1.0, 0.01 + 4.0 * sampled.standardError.x);
        if (r > 0.0f) {
          Estimate integrated = integratedAlbedo(m, outgoing(cosTheta), 400000, ++seed);
          std::printf(" %9.5f", integrated.mean.x);
          EXPECT_NEAR(integrated.mean.x, 1.0, 0.01 + 4.0 * integrated.standardError.x);
        }
        std::printf("\n");
      }
}

// The committed table (shaders/common/bsdf_tables.h) is what integrating
// ggx_reflection.h gives now: a few entries recomputed with fewer samples, and the one
// closed form, E(cos = 1) = 1 - ln 2 at roughness 1 (D = 1 / pi, V = 1 / (2 (1 + cos_i))).
TEST(Energy, GgxAlbedoTableMatchesItsIntegrals) {
  EXPECT_NEAR(gpu::bsdfTableAt(WP_TABLE_GGX_WHITE, 1.0f, 1.0f), 1.0 - std::log(2.0), 1e-5);
  EXPECT_NEAR(gpu::bsdfTableAt(WP_TABLE_GGX_WHITE, 0.0f, 0.3f), 1.0, 1e-6);
  EXPECT_NEAR(gpu::bsdfTableAt(WP_TABLE_GGX_SCHLICK, 0.0f, 15.0f / 31.0f), gpu::schlickWeight(15.0f / 31.0f), 1e-6);
  for (float r : {5.0f / 31.0f, 0.5f - 0.5f / 31.0f, 1.0f})
    for (float cosTheta : {1.0f / 31.0f, 0.5f - 0.5f / 31.0f, 26.0f / 31.0f}) {
      const float alpha = gpu::alphaFromRoughness(r);
      const glm::vec3 o(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
      double white = 0.0, schlick = 0.0;
      constexpr int kGrid = 200;
      for (int a = 0; a < kGrid; ++a)
        for (int b = 0; b < kGrid; ++b) {
          glm::vec2 u((a + 0.5f) / kGrid, (b + 0.5f) / kGrid);
          glm::vec3 wi = gpu::sampleGgxReflection(alpha, o, u);
          gpu::BsdfEval one = gpu::evalGgxReflection(glm::vec3(1.0f), 1.0f, alpha, o, wi);
          gpu::BsdfEval weight = gpu::evalGgxReflection(glm::vec3(0.0f), 1.0f, alpha, o, wi);
          if (one.pdf > 0.0f) {
            white += one.fCos.x / one.pdf;
            schlick += weight.fCos.x / weight.pdf;
          }
        }
      SCOPED_TRACE("r " + std::to_string(r) + " cos " + std::to_string(cosTheta));
      EXPECT_NEAR(gpu::bsdfTableAt(WP_TABLE_GGX_WHITE, r, cosTheta), white / (kGrid * kGrid), 2e-4);
      EXPECT_NEAR(gpu::bsdfTableAt(WP_TABLE_GGX_SCHLICK, r, cosTheta), schlick / (kGrid * kGrid), 2e-4);
    }
}

// KHR_materials_specular: weight 0 leaves a pure Lambertian base (the layer reflects nothing
// and lets everything through); a coloured F0 tints the smooth layer's mirror image by
// Schlick's curve from F0 = specularColor (0.04 from the IOR) to F90 = the weight.
TEST(Specular, WeightAndColourShapeTheDielectricLayer) {
  glm::vec3 wo = outgoing(0.7f);
  TestRandom random(41);
  gpu::SurfaceMaterial none = specular(plastic(0.5f, glm::vec3(0.6f, 0.5f, 0.4f)), glm::vec3(1.0f), 0.0f);
  for (int i = 0; i < 200; ++i) {
    glm::vec3 wi = uniformSphere(random);
    if (wi.z <= 0.01f) continue;
    gpu::BsdfEval e = gpu::evalMaterial(none, wo, wi, 0u);
    for (int k = 0; k < 3; ++k) ASSERT_NEAR(e.fCos[k], none.baseColor[k] * wi.z / kPi, 1e-6f);
  }
  gpu::SurfaceMaterial tinted = specular(plastic(0.0f, glm::vec3(0.0f)), glm::vec3(1.0f, 0.5f, 0.25f), 0.8f);
  gpu::MaterialSample s = gpu::sampleMaterial(tinted, wo, glm::vec3(0.0f, 0.5f, 0.5f), 0u);
  ASSERT_NE(s.flags & WP_SAMPLE_DELTA, 0u);
  const glm::vec3 f0 = glm::vec3(1.0f, 0.5f, 0.25f) * gpu::f0FromIor(1.5f) * 0.8f;
  const glm::vec3 expected = f0 + (glm::vec3(0.8f) - f0) * gpu::schlickWeight(0.7f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(s.weight[k] * s.pdf, expected[k], 1e-6f);
}

// A sheen or coat of strength 0 changes nothing, and a white coat over a white Lambertian
// base still reflects at most 1 while the coat itself reflects its share: the scaled base
// and the coat together (the min form of albedo scaling is conservative, so the sum dips a
// little below 1 at grazing angles, where the two albedos differ most).
TEST(Layers, StrengthZeroIsTheBaseAndAWhiteCoatedLambertStaysNearOne) {
  TestRandom random(43);
  gpu::SurfaceMaterial base = plastic(0.4f, glm::vec3(0.7f, 0.6f, 0.5f));
  gpu::SurfaceMaterial zero = sheened(coated(base, 0.3f), glm::vec3(0.0f));
  zero.clearcoat = 0.0f;
  for (int i = 0; i < 200; ++i) {
    glm::vec3 wo = outgoing(0.1f + 0.8f * random.next()), wi = uniformSphere(random);
    gpu::BsdfEval a = gpu::evalMaterial(base, wo, wi, 0u), b = gpu::evalMaterial(zero, wo, wi, 0u);
    ASSERT_EQ(a.fCos, b.fCos);
    ASSERT_EQ(a.pdf, b.pdf);
  }
  for (float cosTheta : {0.9f, 0.5f, 0.2f}) {
    for (float coatRoughness : {0.0f, 0.5f}) {
      gpu::SurfaceMaterial white = coated(plastic(1.0f, glm::vec3(1.0f)), coatRoughness);
      white.baseColor = glm::vec3(1.0f);
      Estimate sampled = sampledAlbedo(white, outgoing(cosTheta), 0u, 40000, 50);
      SCOPED_TRACE("cos " + std::to_string(cosTheta) + " coat roughness " + std::to_string(coatRoughness));
      EXPECT_LE(sampled.mean.x, 1.0 + 3.0 * sampled.standardError.x);
      EXPECT_GT(sampled.mean.x, 0.9);
    }
  }
}

// The sheen table (bsdf_tables.h) is what integrating sheen.h gives now, at a few entries,
// within 1%: the 300 x 300 grid of cosine samples itself is off by up to 0.7% at grazing
// angles, where the lobe peaks and the cosine density puts few samples.
TEST(Energy, SheenAlbedoTableMatchesItsIntegrals) {
  for (float r : {3.0f / 31.0f, 15.0f / 31.0f, 1.0f})
    for (float cosTheta : {2.0f / 31.0f, 15.0f / 31.0f, 1.0f}) {
      const glm::vec3 o(std::sqrt(1.0f - cosTheta * cosTheta), 0.0f, cosTheta);
      double sum = 0.0;
      constexpr int kGrid = 300;
      for (int a = 0; a < kGrid; ++a)
        for (int b = 0; b < kGrid; ++b) {
          glm::vec3 wi = gpu::sampleSheen(glm::vec2((a + 0.5f) / kGrid, (b + 0.5f) / kGrid));
          gpu::BsdfEval e = gpu::evalSheen(glm::vec3(1.0f), r, o, wi);
          if (e.pdf > 0.0f) sum += e.fCos.x / e.pdf;
        }
      SCOPED_TRACE("r " + std::to_string(r) + " cos " + std::to_string(cosTheta));
      const double integral = sum / (kGrid * kGrid);
      EXPECT_NEAR(gpu::bsdfTableAt(WP_TABLE_SHEEN, r, cosTheta), integral, 0.01 * integral);
    }
}

// ---- Reciprocity ----------------------------------------------------------------------

// Whether float arithmetic can evaluate a refraction pair to 1e-4 both ways round. Not
// within 6 degrees of the microfacet's horizon: near the critical angle the transmittance
// 1 - F has unbounded slope. Nor where D is too steep: the half vector o + eta i (not
// symmetric in o and i, unlike reflection's) is rounded by about 1e-7 (1 + tan^2) in
// tan(theta_m), which moves Beckmann's exponent tan^2 / alpha^2 by twice that times
// tan / alpha^2.
bool wellConditioned(const gpu::SurfaceMaterial& m, glm::vec3 wo, glm::vec3 wi) {
  if (wo.z * wi.z > 0.0f) return true;
  double nO = wo.z > 0.0f ? 1.0 : m.ior, nI = wi.z > 0.0f ? 1.0 : m.ior;
  glm::dvec3 h = glm::normalize(nO * glm::dvec3(wo) + nI * glm::dvec3(wi));
  if (h.z < 0.0) h = -h;
  double alpha = double(m.roughness) * m.roughness, tanTheta = std::sqrt(1.0 - h.z * h.z) / h.z;
  double exponentError = 2e-7 * (1.0 + tanTheta * tanTheta) * tanTheta / (alpha * alpha);
  return std::fabs(glm::dot(h, glm::dvec3(wo))) > 0.1 && std::fabs(glm::dot(h, glm::dvec3(wi))) > 0.1 &&
         exponentError < 2e-5;
}

// f(wo, wi) / n(wo's side)^2 = f(wi, wo) / n(wi's side)^2: plain reciprocity for
// reflection, and for refraction the generalized form of radiance transport. Half the
// pairs are uniform, half sampled from the BSDF so that narrow lobes are covered.
void expectReciprocal(const gpu::SurfaceMaterial& m, uint64_t seed) {
  TestRandom random(seed);
  int nonZero = 0;
  double worst = 0;
  for (int i = 0; i < 20000; ++i) {
    glm::vec3 wo = uniformSphere(random), wi = uniformSphere(random);
    if (i % 2 == 1) {
      gpu::MaterialSample s = gpu::sampleMaterial(m, wo, next3(random), 0u);
      if (!(s.pdf > 0.0f) || (s.flags & WP_SAMPLE_DELTA)) continue;
      wi = s.wi;
    }
    if (std::fabs(wo.z) < 0.01f || std::fabs(wi.z) < 0.01f || !wellConditioned(m, wo, wi)) continue;
    glm::vec3 forward = gpu::evalMaterial(m, wo, wi, 0u).fCos / std::fabs(wi.z);
    glm::vec3 backward = gpu::evalMaterial(m, wi, wo, 0u).fCos / std::fabs(wo.z);
    double nO = wo.z > 0.0f ? 1.0 : m.ior, nI = wi.z > 0.0f ? 1.0 : m.ior;
    for (int k = 0; k < 3; ++k) {
      double a = forward[k] / (nO * nO), b = backward[k] / (nI * nI);
      double scale = std::max(std::fabs(a), std::fabs(b));
      if (scale == 0.0) continue;
      ++nonZero;
      worst = std::max(worst, std::fabs(a - b) / scale);
    }
  }
  EXPECT_GT(nonZero, 10000);
  EXPECT_LT(worst, 1e-4);
}

TEST(Reciprocity, EveryMaterialIsReciprocal) {
  uint64_t seed = 200;
  for (float r : {0.05f, 0.3f, 0.7f, 1.0f}) {
    SCOPED_TRACE("roughness " + std::to_string(r));
    {
      SCOPED_TRACE("metal");
      expectReciprocal(metal(r), ++seed);
    }
    {
      SCOPED_TRACE("plastic");
      expectReciprocal(plastic(r), ++seed);
      expectReciprocal(plastic(r, glm::vec3(0.9f, 0.1f, 0.5f)), ++seed);
    }
    {
      SCOPED_TRACE("glass");
      expectReciprocal(glass(r, glm::vec3(0.9f, 0.8f, 0.7f)), ++seed);
    }
    {
      SCOPED_TRACE("mixed");
      expectReciprocal(mixed(r), ++seed);
    }
    {
      // The coat's normal is the shading normal here: with a tilted one (a coat normal map)
      // the coat's f |cos| takes the cosine about its own normal while the base's takes the
      // base's, so f = fCos / |cos_i| about the base's normal is not reciprocal, as no
      // shading normal is (Veach 1997, 5.3); TiltedCoat's samples still follow its pdf.
      SCOPED_TRACE("layers");
      expectReciprocal(coated(sheened(plastic(r)), r), ++seed);
      expectReciprocal(specular(coated(metal(r), 0.5f), glm::vec3(0.2f, 0.9f, 0.5f), 0.6f), ++seed);
    }
  }
}

// ---- Sample, eval and pdf agree ------------------------------------------------------------

// For random wo and u: a sample's pdf is pdfMaterial's, its weight is evalMaterial's
// f |cos| over that pdf, its direction is a unit vector, and its transmission flag says
// whether it crossed the surface.
TEST(Consistency, SampleAgreesWithEvalAndPdf) {
  TestRandom random(300);
  for (float r : {0.05f, 0.3f, 0.7f, 1.0f})
    for (const gpu::SurfaceMaterial& m :
         {metal(r), plastic(r), glass(r, glm::vec3(0.9f, 0.8f, 0.7f)), mixed(r), coated(sheened(mixed(r)), r),
          specular(coated(plastic(r), r, glm::vec3(-0.3f, 0.2f, 0.9f)), glm::vec3(0.5f, 1.0f, 0.8f), 0.5f)})
      for (uint32_t flags : {0u, uint32_t(WP_BSDF_WIDEN_BECKMANN)}) {
        int valid = 0;
        for (int i = 0; i < 2000; ++i) {
          glm::vec3 wo = uniformSphere(random);
          gpu::MaterialSample s = gpu::sampleMaterial(m, wo, next3(random), flags);
          if (!(s.pdf > 0.0f)) continue;
          ++valid;
          ASSERT_EQ(s.flags & WP_SAMPLE_DELTA, 0u);
          ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-5f);
          ASSERT_EQ((s.flags & WP_SAMPLE_TRANSMISSION) != 0u, wo.z * s.wi.z < 0.0f);
          gpu::BsdfEval e = gpu::evalMaterial(m, wo, s.wi, flags);
          float pdf = gpu::pdfMaterial(m, wo, s.wi, flags);
          ASSERT_NEAR(pdf, s.pdf, 1e-4f * s.pdf) << "roughness " << r << " metallic " << m.metallic;
          ASSERT_NEAR(e.pdf, s.pdf, 1e-4f * s.pdf);
          for (int k = 0; k < 3; ++k) {
            float expected = e.fCos[k] / e.pdf;
            ASSERT_TRUE(std::isfinite(s.weight[k]));
            ASSERT_NEAR(s.weight[k], expected, 1e-4f * std::max(expected, 1e-3f));
          }
        }
        EXPECT_GT(valid, 500) << "roughness " << r << " metallic " << m.metallic;
      }
}

// The widened sampling roughness changes where samples go, never the BSDF itself.
TEST(Consistency, WidenedSamplingKeepsTheBsdf) {
  TestRandom random(301);
  gpu::SurfaceMaterial m = glass(0.5f);
  int differentPdf = 0;
  for (int i = 0; i < 1000; ++i) {
    glm::vec3 wo = uniformSphere(random), wi = uniformSphere(random);
    gpu::BsdfEval plain = gpu::evalMaterial(m, wo, wi, 0u);
    gpu::BsdfEval widened = gpu::evalMaterial(m, wo, wi, WP_BSDF_WIDEN_BECKMANN);
    ASSERT_EQ(plain.fCos, widened.fCos);
    if (plain.pdf != widened.pdf) ++differentPdf;
  }
  EXPECT_GT(differentPdf, 300);
}

// No input, however grazing or degenerate, yields NaN, inf or a negative pdf or weight.
TEST(Consistency, DegenerateInputsGiveFiniteResults) {
  const float zs[] = {1.0f, 0.5f, 1e-4f, 1e-6f, 1e-8f, 0.0f, -1e-8f, -1e-6f, -1e-4f, -0.5f, -1.0f};
  const float us[] = {0.0f, 1e-7f, 0.5f, 0.99999994f};
  std::vector<gpu::SurfaceMaterial> materials;
  for (float r : {0.0f, 0.02f, 0.04f, 0.3f, 1.0f})
    for (float ior : {1.0f, 1.0005f, 1.5f, 2.4f}) {
      materials.push_back(makeMaterial(glm::vec3(1.0f), 1.0f, r, ior, 0.0f));
      materials.push_back(makeMaterial(glm::vec3(0.0f), 0.0f, r, ior, 0.0f));
      materials.push_back(makeMaterial(glm::vec3(1.0f), 0.0f, r, ior, 1.0f));
      materials.push_back(makeMaterial(glm::vec3(0.5f), 0.3f, r, ior, 0.6f));
    }
  for (const gpu::SurfaceMaterial& m : materials)
    for (float z : zs) {
      float t = std::sqrt(std::max(0.0f, 1.0f - z * z));
      glm::vec3 wo(t * 0.6f, t * 0.8f, z);
      for (float u0 : us)
        for (float u1 : us)
          for (float u2 : us)
            for (uint32_t flags : {0u, uint32_t(WP_BSDF_WIDEN_BECKMANN)}) {
              gpu::MaterialSample s = gpu::sampleMaterial(m, wo, glm::vec3(u0, u1, u2), flags);
              ASSERT_TRUE(allFinite(s.wi) && allFinite(s.weight) && std::isfinite(s.pdf));
              ASSERT_GE(s.pdf, 0.0f);
              ASSERT_GE(std::min(s.weight.x, std::min(s.weight.y, s.weight.z)), 0.0f);
              for (float wz : zs) {
                float wt = std::sqrt(std::max(0.0f, 1.0f - wz * wz));
                gpu::BsdfEval e = gpu::evalMaterial(m, wo, glm::vec3(-wt * u1, wt * std::sqrt(1.0f - u1 * u1), wz),
                                                    flags);
                ASSERT_TRUE(allFinite(e.fCos) && std::isfinite(e.pdf) && e.pdf >= 0.0f);
              }
            }
    }
}

// ---- Delta lobes ------------------------------------------------------------------------

TEST(Delta, SmoothMetalIsAMirror) {
  glm::vec3 f0(0.9f, 0.5f, 0.2f);
  for (float z : {0.9f, 0.3f, -0.6f}) {
    glm::vec3 wo = outgoing(z);
    gpu::MaterialSample s = gpu::sampleMaterial(metal(0.0f, f0), wo, glm::vec3(0.3f, 0.6f, 0.9f), 0u);
    EXPECT_EQ(s.wi, glm::vec3(-wo.x, -wo.y, wo.z));
    EXPECT_EQ(s.flags, uint32_t(WP_SAMPLE_DELTA));
    EXPECT_EQ(s.pdf, 1.0f);
    EXPECT_EQ(s.weight, gpu::fresnelSchlick(f0, std::fabs(z)));
    gpu::BsdfEval e = gpu::evalMaterial(metal(0.0f, f0), wo, s.wi, 0u);
    EXPECT_EQ(e.fCos, glm::vec3(0.0f));
    EXPECT_EQ(e.pdf, 0.0f);
    EXPECT_EQ(gpu::pdfMaterial(metal(0.0f, f0), wo, s.wi, 0u), 0.0f);
  }
}

// Exact Fresnel reflectance in double, written from the textbook s/p amplitudes.
double referenceFresnel(double cosI, double eta) {
  double sin2T = (1.0 - cosI * cosI) / (eta * eta);
  if (sin2T >= 1.0) return 1.0;
  double cosT = std::sqrt(1.0 - sin2T);
  double rs = (cosI - eta * cosT) / (cosI + eta * cosT), rp = (eta * cosI - cosT) / (eta * cosI + cosT);
  return 0.5 * (rs * rs + rp * rp);
}

// Smooth glass reflects with the probability of the exact Fresnel term (within 5 binomial
// standard deviations) and refracts by Snell's law; its lobes are invisible to eval and pdf.
TEST(Delta, SmoothGlassFollowsFresnelAndSnell) {
  glm::vec3 tint(0.9f, 0.7f, 0.5f);
  gpu::SurfaceMaterial m = glass(0.0f, tint);
  constexpr int kCount = 100000;
  // From outside, from inside, and from inside beyond the critical angle (always reflects).
  for (float z : {0.9f, 0.5f, 0.1f, -0.9f, -0.8f, -0.6f}) {
    SCOPED_TRACE("cos " + std::to_string(z));
    glm::vec3 wo = outgoing(z);
    double nO = z > 0.0f ? 1.0 : m.ior, nI = z > 0.0f ? m.ior : 1.0, eta = nI / nO;
    TestRandom random(400);
    int reflected = 0;
    for (int i = 0; i < kCount; ++i) {
      gpu::MaterialSample s = gpu::sampleMaterial(m, wo, next3(random), 0u);
      ASSERT_TRUE(s.flags & WP_SAMPLE_DELTA);
      ASSERT_EQ(gpu::pdfMaterial(m, wo, s.wi, 0u), 0.0f);
      ASSERT_EQ(gpu::evalMaterial(m, wo, s.wi, 0u).fCos, glm::vec3(0.0f));
      if (!(s.flags & WP_SAMPLE_TRANSMISSION)) {
        ++reflected;
        ASSERT_EQ(s.wi, glm::vec3(-wo.x, -wo.y, wo.z));
        ASSERT_EQ(s.weight, glm::vec3(1.0f));
        continue;
      }
      ASSERT_LT(s.wi.z * wo.z, 0.0f);
      // Snell: n_o sin(theta_o) = n_i sin(theta_i), in the plane of incidence, opposite side.
      double sinO = std::hypot(wo.x, wo.y), sinI = std::hypot(s.wi.x, s.wi.y);
      ASSERT_NEAR(nO * sinO, nI * sinI, 1e-5);
      ASSERT_NEAR(wo.x * s.wi.y - wo.y * s.wi.x, 0.0, 1e-6);
      ASSERT_LT(wo.x * s.wi.x + wo.y * s.wi.y, 0.0f);
      ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-6f);
      glm::dvec3 expectedWeight = glm::dvec3(tint) / (eta * eta);
      for (int k = 0; k < 3; ++k) ASSERT_NEAR(s.weight[k], expectedWeight[k], 1e-6);
    }
    double f = referenceFresnel(std::fabs(z), eta);
    EXPECT_NEAR(reflected, kCount * f, 5.0 * std::sqrt(kCount * f * (1.0 - f)) + 1e-9);
  }
}

// A smooth plastic's coat is a delta mirror picked with plasticSpecularProbability; its
// diffuse samples still agree with eval and pdf.
TEST(Delta, SmoothPlasticMixesAMirrorAndDiffuse) {
  glm::vec3 albedo(0.6f, 0.5f, 0.4f);
  gpu::SurfaceMaterial m = plastic(0.0f, albedo);
  glm::vec3 wo = outgoing(0.3f);
  float f0 = gpu::f0FromIor(m.ior);
  float p = gpu::plasticSpecularProbability(albedo, gpu::specularLayerOf(m), 0.0f, 0.3f, 0u);
  TestRandom random(500);
  int mirrors = 0;
  constexpr int kCount = 20000;
  for (int i = 0; i < kCount; ++i) {
    gpu::MaterialSample s = gpu::sampleMaterial(m, wo, next3(random), 0u);
    ASSERT_GT(s.pdf, 0.0f);
    if (s.flags & WP_SAMPLE_DELTA) {
      ++mirrors;
      ASSERT_EQ(s.wi, glm::vec3(-wo.x, -wo.y, wo.z));
      ASSERT_FLOAT_EQ(s.pdf, p);
      ASSERT_FLOAT_EQ(s.weight.x, gpu::fresnelSchlickScalar(f0, 0.3f) / p);
    } else {
      ASSERT_NEAR(gpu::pdfMaterial(m, wo, s.wi, 0u), s.pdf, 1e-5f * s.pdf);
    }
  }
  EXPECT_NEAR(mirrors, kCount * p, 5.0 * std::sqrt(kCount * p * (1.0 - p)));
}

// A smooth clear coat is a delta mirror about its own normal (here tilted), picked with the
// coat's Fresnel reflectance (its albedo at roughness 0) and weighted by it over that
// probability (so the two multiply to F exactly); eval and pdf do not see it, and the samples of the layers below it still
// agree with eval and pdf. (The chi-square test cannot see a delta lobe, hence this one.)
TEST(Delta, SmoothCoatIsAMirrorAboutItsNormal) {
  const glm::vec3 coatNormal = glm::normalize(glm::vec3(0.3f, -0.2f, 0.9f));
  gpu::SurfaceMaterial m = coated(plastic(0.6f, glm::vec3(0.6f, 0.5f, 0.4f)), 0.0f, coatNormal);
  // From above and below, each with its mirror direction on wo's side of the surface.
  for (float z : {0.8f, 0.4f, -0.7f}) {
    SCOPED_TRACE("cos " + std::to_string(z));
    const glm::vec3 wo = outgoing(z);
    const glm::vec3 n = z > 0.0f ? coatNormal : glm::vec3(-coatNormal.x, -coatNormal.y, -coatNormal.z);
    const float cosCoat = glm::dot(wo, n);
    const glm::vec3 mirror = 2.0f * cosCoat * n - wo;
    const float p = gpu::fresnelSchlickScalar(WP_COAT_F0, cosCoat);
    TestRandom random(510);
    int mirrors = 0;
    constexpr int kCount = 20000;
    for (int i = 0; i < kCount; ++i) {
      gpu::MaterialSample s = gpu::sampleMaterial(m, wo, next3(random), 0u);
      if (!(s.pdf > 0.0f)) continue;
      if (s.flags & WP_SAMPLE_DELTA) {
        ++mirrors;
        for (int k = 0; k < 3; ++k) ASSERT_NEAR(s.wi[k], mirror[k], 1e-5f);
        ASSERT_NEAR(s.pdf, p, 1e-2f * p);  // the coat's albedo table, interpolated in cos
        ASSERT_NEAR(s.weight.x * s.pdf, p, 1e-5f);
        const gpu::BsdfEval atMirror = gpu::evalMaterial(m, wo, s.wi, 0u);
        const gpu::BsdfEval baseAtMirror = gpu::evalBaseMaterial(m, wo, s.wi, 0u);
        ASSERT_LE(atMirror.fCos.x, baseAtMirror.fCos.x);  // the base, scaled; no coat lobe
      } else {
        ASSERT_NEAR(gpu::pdfMaterial(m, wo, s.wi, 0u), s.pdf, 1e-5f * s.pdf);
      }
    }
    EXPECT_NEAR(mirrors, kCount * p, 5.0 * std::sqrt(kCount * p * (1.0 - p)));
  }
}

// In a mixed material a delta sample's pdf is the probability of its lobe times that of
// the delta direction within it, and its weight is the lobe's own.
TEST(Delta, MixedMaterialScalesDeltaProbabilities) {
  glm::vec3 base(0.8f, 0.6f, 0.4f);
  gpu::SurfaceMaterial m = mixed(0.0f, base);  // metal 1/2, glass 1/4, plastic 1/4
  glm::vec3 wo = outgoing(0.6f);
  float fGlass = gpu::fresnelDielectric(0.6f, m.ior);
  float pPlastic = gpu::plasticSpecularProbability(base, gpu::specularLayerOf(m), 0.0f, 0.6f, 0u);
  // u.x < 1/2: metal; then glass reflects, glass refracts, plastic's mirror.
  gpu::MaterialSample s = gpu::sampleMaterial(m, wo, glm::vec3(0.2f, 0.5f, 0.5f), 0u);
  EXPECT_EQ(s.pdf, 0.5f);
  EXPECT_EQ(s.weight, gpu::fresnelSchlick(base, 0.6f));
  s = gpu::sampleMaterial(m, wo, glm::vec3(0.5f + 0.25f * 0.5f * fGlass, 0.5f, 0.5f), 0u);
  EXPECT_FLOAT_EQ(s.pdf, 0.25f * fGlass);
  EXPECT_EQ(s.flags, uint32_t(WP_SAMPLE_DELTA));
  s = gpu::sampleMaterial(m, wo, glm::vec3(0.5f + 0.25f * (fGlass + 1.0f) * 0.5f, 0.5f, 0.5f), 0u);
  EXPECT_FLOAT_EQ(s.pdf, 0.25f * (1.0f - fGlass));
  EXPECT_EQ(s.flags, uint32_t(WP_SAMPLE_DELTA | WP_SAMPLE_TRANSMISSION));
  s = gpu::sampleMaterial(m, wo, glm::vec3(0.75f + 0.25f * 0.5f * pPlastic, 0.5f, 0.5f), 0u);
  EXPECT_FLOAT_EQ(s.pdf, 0.25f * pPlastic);
  EXPECT_EQ(s.flags, uint32_t(WP_SAMPLE_DELTA));
}

// ---- Fresnel ------------------------------------------------------------------------------

TEST(Fresnel, DielectricAtKnownAngles) {
  // Normal incidence: ((n - 1) / (n + 1))^2 from either side.
  EXPECT_NEAR(gpu::fresnelDielectric(1.0f, 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(gpu::fresnelDielectric(1.0f, 1.0f / 1.5f), 0.04f, 1e-6f);
  EXPECT_NEAR(gpu::f0FromIor(1.5f), 0.04f, 1e-7f);
  EXPECT_NEAR(gpu::fresnelDielectric(1.0f, 2.4f), (1.4f / 3.4f) * (1.4f / 3.4f), 1e-6f);
  // 45 degrees into glass: R_s = 0.0920, R_p = 0.0085, mean 0.0502.
  EXPECT_NEAR(gpu::fresnelDielectric(std::sqrt(0.5f), 1.5f), 0.050240f, 1e-5f);
  // Brewster's angle (tan = n): p is not reflected, so F = R_s / 2 = ((n^2-1)/(n^2+1))^2 / 2.
  float brewster = float(std::cos(std::atan(1.5)));
  EXPECT_NEAR(gpu::fresnelDielectric(brewster, 1.5f), 0.5f * std::pow(1.25f / 3.25f, 2.0f), 1e-6f);
  // Grazing incidence reflects everything.
  EXPECT_NEAR(gpu::fresnelDielectric(0.0f, 1.5f), 1.0f, 1e-6f);
  // Inside glass the critical angle is asin(1 / 1.5), cos = 0.745356: beyond it, total
  // internal reflection; just before it, not yet.
  EXPECT_EQ(gpu::fresnelDielectric(0.745f, 1.0f / 1.5f), 1.0f);
  EXPECT_EQ(gpu::fresnelDielectric(0.3f, 1.0f / 1.5f), 1.0f);
  EXPECT_LT(gpu::fresnelDielectric(0.75f, 1.0f / 1.5f), 0.5f);
}

// Reflectance is the same for a refraction pair seen from either side.
TEST(Fresnel, DielectricIsSymmetricUnderRefraction) {
  for (float cosI : {0.95f, 0.7f, 0.4f, 0.1f}) {
    float sinT = std::sqrt(1.0f - cosI * cosI) / 1.5f, cosT = std::sqrt(1.0f - sinT * sinT);
    EXPECT_NEAR(gpu::fresnelDielectric(cosI, 1.5f), gpu::fresnelDielectric(cosT, 1.0f / 1.5f), 1e-6f);
    EXPECT_NEAR(gpu::fresnelDielectric(cosI, 1.5f), referenceFresnel(cosI, 1.5), 1e-6);
  }
}

TEST(Fresnel, SchlickAtKnownAngles) {
  glm::vec3 f0(0.9f, 0.5f, 0.04f);
  EXPECT_EQ(gpu::fresnelSchlick(f0, 1.0f), f0);
  EXPECT_EQ(gpu::fresnelSchlick(f0, 0.0f), glm::vec3(1.0f));
  glm::vec3 half = gpu::fresnelSchlick(f0, 0.5f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(half[k], f0[k] + (1.0f - f0[k]) / 32.0f, 1e-7f);
  // Its cosine-weighted mean: 2 * integral of F(mu) mu dmu, by the midpoint rule.
  double mean = 0;
  constexpr int kSteps = 100000;
  for (int i = 0; i < kSteps; ++i) {
    double mu = (i + 0.5) / kSteps;
    mean += 2.0 * gpu::fresnelSchlickScalar(0.04f, float(mu)) * mu / kSteps;
  }
  EXPECT_NEAR(gpu::fresnelSchlickAverage(glm::vec3(0.04f)).x, mean, 1e-6);
}

// ---- Microfacet terms and the diffuse lobe ------------------------------------------------

// Frostbite's V equals the height-correlated Smith G2 / (4 cos_o cos_i) written out from
// Heitz 2014: Lambda = (sqrt(1 + alpha^2 tan^2) - 1) / 2, G2 = 1 / (1 + Lambda_o + Lambda_i).
TEST(Microfacet, GgxVisibilityIsHeightCorrelatedSmith) {
  auto lambda = [](double alpha, double c) { return 0.5 * (std::sqrt(1.0 + alpha * alpha * (1.0 - c * c) / (c * c)) - 1.0); };
  for (double alpha : {0.01, 0.2, 0.5, 1.0})
    for (double cosO : {0.05, 0.4, 0.9, 1.0})
      for (double cosI : {0.1, 0.7, 0.99}) {
        double g2 = 1.0 / (1.0 + lambda(alpha, cosO) + lambda(alpha, cosI));
        double expected = g2 / (4.0 * cosO * cosI);
        EXPECT_NEAR(gpu::ggxVisibility(float(alpha), float(cosO), float(cosI)), expected, 1e-5 * expected);
      }
}

// Walter et al.'s rational G1 stays within 0.4% of the exact Beckmann Smith term
// 2 / (1 + erf(a) + exp(-a^2) / (a sqrt(pi))), a = 1 / (alpha tan(theta)).
TEST(Microfacet, BeckmannG1MatchesTheErfForm) {
  for (double alpha : {0.05, 0.3, 1.0})
    for (double c = 0.02; c < 1.0; c += 0.02) {
      double a = c / (alpha * std::sqrt(1.0 - c * c));
      double exact = 2.0 / (1.0 + std::erf(a) + std::exp(-a * a) / (a * std::sqrt(kPi)));
      EXPECT_NEAR(gpu::beckmannG1(float(alpha), float(c)), exact, 0.004 * exact) << "alpha " << alpha << " cos " << c;
    }
  EXPECT_EQ(gpu::beckmannG1(0.3f, 1.0f), 1.0f);
}

// Burley's diffuse at known points: no retro-reflection term at normal incidence, where
// only Frostbite's energy factor 1 / 1.51 (at roughness 1) remains; F_D90 =
// 0.5 r + 2 r cos^2(theta_d) at grazing view; a smooth surface darkens at grazing angles.
TEST(Microfacet, DisneyDiffuseAtKnownValues) {
  EXPECT_NEAR(gpu::disneyDiffuseFactor(1.0f, 1.0f, 1.0f, 1.0f), 1.0f / 1.51f, 1e-6f);
  EXPECT_NEAR(gpu::disneyDiffuseFactor(0.0f, 1.0f, 1.0f, 1.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(gpu::disneyDiffuseFactor(1.0f, 0.0f, 1.0f, std::sqrt(0.5f)), 1.5f / 1.51f, 1e-6f);
  EXPECT_NEAR(gpu::disneyDiffuseFactor(0.0f, 0.0f, 1.0f, std::sqrt(0.5f)), 0.0f, 1e-6f);
  EXPECT_NEAR(gpu::disneyDiffuseFactor(0.5f, 0.5f, 0.5f, 0.8f),
              std::pow(1.0f + (0.25f + 0.64f - 1.0f) / 32.0f, 2.0f) * (1.0f + 0.5f * (1.0f / 1.51f - 1.0f)), 1e-6f);
}

// ---- Beer's law and the contribution clamp --------------------------------------------------

TEST(Volume, BeerLawAtKnownValues) {
  glm::vec3 color(0.5f, 0.25f, 1.0f);
  // At the attenuation distance the transmittance is the attenuation colour.
  glm::vec3 t = gpu::beerLawTransmittance(color, 2.0f, 2.0f);
  for (int k = 0; k < 3; ++k) EXPECT_NEAR(t[k], color[k], 1e-6f);
  // Twice as far: squared; half as far: the square root; T = exp(-sigma d).
  t = gpu::beerLawTransmittance(color, 2.0f, 4.0f);
  EXPECT_NEAR(t.x, 0.25f, 1e-6f);
  EXPECT_NEAR(t.y, 0.0625f, 1e-6f);
  EXPECT_NEAR(t.z, 1.0f, 1e-6f);
  t = gpu::beerLawTransmittance(color, 2.0f, 1.0f);
  EXPECT_NEAR(t.x, std::sqrt(0.5f), 1e-6f);
  float sigma = -std::log(0.25f) / 2.0f;
  EXPECT_NEAR(gpu::beerLawTransmittance(color, 2.0f, 0.7f).y, std::exp(-sigma * 0.7f), 1e-6f);
  EXPECT_EQ(gpu::beerLawTransmittance(color, 2.0f, 0.0f), glm::vec3(1.0f));
  // glTF's default attenuation distance is infinite: no absorption.
  EXPECT_EQ(gpu::beerLawTransmittance(color, INFINITY, 100.0f), glm::vec3(1.0f));
  EXPECT_EQ(gpu::beerLawTransmittance(color, WP_FLT_MAX, 100.0f), glm::vec3(1.0f));
  // A black attenuation colour absorbs everything after any distance.
  EXPECT_EQ(gpu::beerLawTransmittance(glm::vec3(0.0f), 1.0f, 1e-3f), glm::vec3(0.0f));
}

TEST(Volume, ClampKeepsHueAndLimitsLuminance) {
  glm::vec3 c(30.0f, 10.0f, 5.0f);
  glm::vec3 clamped = gpu::clampContribution(c, 4.0f);
  EXPECT_NEAR(gpu::luminance(clamped), 4.0f, 1e-5f);
  EXPECT_NEAR(clamped.x / clamped.y, 3.0f, 1e-5f);
  EXPECT_EQ(gpu::clampContribution(glm::vec3(0.1f, 0.2f, 0.3f), 4.0f), glm::vec3(0.1f, 0.2f, 0.3f));
}

}  // namespace
