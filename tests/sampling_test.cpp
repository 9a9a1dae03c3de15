// Chi-square and exact-formula tests of the portable sampling code the GPU runs: cosine
// hemisphere, light triangles, the light alias table and the RNG.
#include "shaders/common/sampling.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "shaders/common/lights.h"
#include "shaders/common/rng.h"
#include "support/chi_square.h"

namespace {

namespace gpu = wp::gpu;
using wp::test::chiSquareTest;
using wp::test::SphereBinning;
using wp::test::TestRandom;

// The chi-square tests below (1 cosine + 6 triangles + 2 alias tables + 4 RNG). Each runs at
// the Šidák-corrected level, so a correct implementation fails the suite with probability
// 1% over the choice of seeds; the seeds are fixed, so results are deterministic.
constexpr int kChiSquareTests = 13;
const double kAlpha = wp::test::sidakAlpha(0.01, kChiSquareTests);
constexpr int kSamples = 1000000;

glm::vec2 next2(TestRandom& random) {
  float u = random.next();
  return {u, random.next()};
}

// ---- Orthonormal frames --------------------------------------------------------------------

float largestDifference(const gpu::Frame& a, const gpu::Frame& b) {
  const glm::vec3 d = glm::max(glm::abs(a.tangent - b.tangent), glm::abs(a.bitangent - b.bitangent));
  return std::max({d.x, d.y, d.z});
}

TEST(Frame, IsOrthonormalAndRightHandedForNormalsAllOverTheSphere) {
  TestRandom random(7);
  for (int i = 0; i < 100000; ++i) {
    const glm::vec2 u = next2(random);
    const float z = 1.0f - 2.0f * u.x;  // uniform over the sphere
    const float rest = std::sqrt(std::max(0.0f, 1.0f - z * z));
    const glm::vec3 n(rest * std::cos(6.2831853f * u.y), rest * std::sin(6.2831853f * u.y), z);
    const gpu::Frame f = gpu::makeFrame(n);
    ASSERT_NEAR(glm::length(f.tangent), 1.0f, 1e-5f) << "n = " << n.x << " " << n.y << " " << n.z;
    ASSERT_NEAR(glm::length(f.bitangent), 1.0f, 1e-5f);
    ASSERT_NEAR(glm::dot(f.tangent, f.bitangent), 0.0f, 1e-5f);
    ASSERT_NEAR(glm::dot(f.tangent, n), 0.0f, 1e-5f);
    ASSERT_NEAR(glm::dot(f.bitangent, n), 0.0f, 1e-5f);
    ASSERT_GT(glm::dot(glm::cross(f.tangent, f.bitangent), n), 0.999f);
  }
}

TEST(Frame, NormalsOfRoundAnglesGetTheSameFrameWhateverTheirRounding) {
  // The normals of faces at 0, 30, 45, 60 and 90 degrees, where modelled geometry lies, each
  // nudged by the rounding a fused or unfused cross product leaves (1e-7 and less): the frame
  // must not jump there, or devices that round differently turn the same random numbers into
  // different directions. Duff et al.'s frame jumped at n.z = 0: a wall of the Cornell box.
  const float roundCosines[] = {0.0f, 0.5f, 0.70710678f, 0.8660254f, 1.0f};
  for (float c : roundCosines) {
    for (float sign : {1.0f, -1.0f}) {
      const float z = sign * c;
      const float rest = std::sqrt(std::max(0.0f, 1.0f - z * z));
      for (float azimuth : {0.0f, 0.3f, 1.2f, 2.5f, 4.0f}) {
        const glm::vec3 n(rest * std::cos(azimuth), rest * std::sin(azimuth), z);
        for (float nudge : {1e-10f, 1e-7f}) {
          const gpu::Frame above = gpu::makeFrame(glm::normalize(n + glm::vec3(0, 0, nudge)));
          const gpu::Frame below = gpu::makeFrame(glm::normalize(n - glm::vec3(0, 0, nudge)));
          EXPECT_LT(largestDifference(above, below), 1e-5f) << "n = " << n.x << " " << n.y << " " << n.z;
        }
      }
    }
  }
}

// ---- Cosine hemisphere ---------------------------------------------------------------------

TEST(CosineHemisphere, SamplesFollowCosineHemispherePdf) {
  TestRandom random(1);
  std::vector<glm::dvec3> directions;
  directions.reserve(kSamples);
  double worstLengthError = 0, lowestZ = 1;
  for (int i = 0; i < kSamples; ++i) {
    glm::vec3 d = gpu::sampleCosineHemisphere(next2(random));
    worstLengthError = std::max(worstLengthError, std::fabs(double(glm::length(d)) - 1.0));
    lowestZ = std::min(lowestZ, double(d.z));
    directions.push_back(d);
  }
  EXPECT_LT(worstLengthError, 1e-5);
  EXPECT_GE(lowestZ, 0.0);
  SphereBinning binning(10, 20);
  auto pdf = [](glm::dvec3 d) { return double(gpu::cosineHemispherePdf(float(d.z))); };
  auto result = chiSquareTest(binning.histogram(directions), binning.expectedCounts(pdf, kSamples));
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

TEST(CosineHemisphere, PdfIntegratesToOne) {
  // The grid has a row boundary at the horizon where the density's kink is, so the
  // integration is accurate to its tolerance.
  auto cells = SphereBinning(10, 20).expectedCounts(
      [](glm::dvec3 d) { return double(gpu::cosineHemispherePdf(float(d.z))); }, 1.0, 8);
  double integral = 0;
  for (double c : cells) integral += c;
  EXPECT_NEAR(integral, 1.0, 1e-6);
}

// ---- Light triangles -----------------------------------------------------------------------

struct TriangleCase {
  const char* name;
  glm::dvec3 v0, v1, v2;
  glm::dvec3 position;  // the shading point
  bool doubleSided;
};

const TriangleCase kTriangleCases[] = {
    {"Facing", {-0.5, -0.5, 3}, {0.7, -0.4, 3.2}, {0.1, 0.6, 2.9}, {0, 0, 0}, false},
    // The same triangle wound the other way: seen from behind a one-sided light.
    {"BackFacing", {-0.5, -0.5, 3}, {0.1, 0.6, 2.9}, {0.7, -0.4, 3.2}, {0, 0, 0}, false},
    // Spans almost the whole upper hemisphere; the density varies ~400x across it.
    {"LargeAndClose", {-6, -5, 1}, {7, -4, 1}, {0, 8, 1}, {0.3, 0.2, 0.75}, false},
    {"Thin", {-2, -0.02, 3}, {2, 0.03, 3}, {0.5, 0.06, 3.1}, {0, 0, 0}, false},
    // Seen nearly edge-on (|cos| at the light around 0.1).
    {"Grazing", {0.3, -1, 2}, {0.35, 1, 2.5}, {0.4, 0, 4}, {0, 0, 0}, true},
    {"SmallAndFar", {10, 5, 15}, {10.3, 5, 15.1}, {10, 5.2, 15}, {0.5, -0.5, 0}, true},
};

gpu::GpuLight makeLight(const TriangleCase& c, float selectionProbability) {
  glm::dvec3 e1 = c.v1 - c.v0, e2 = c.v2 - c.v0;
  gpu::GpuLight light{};
  light.v0 = glm::vec4(glm::vec3(c.v0), float(0.5 * glm::length(glm::cross(e1, e2))));
  light.edge1 = glm::vec4(glm::vec3(e1), selectionProbability);
  light.edge2 = glm::vec4(glm::vec3(e2), 1.0f);
  // w: the selection weight by solid angle, the luminance of an untextured light.
  light.emission = glm::vec4(1.0f, 2.0f, 3.0f, 0.2126f + 0.7152f * 2.0f + 0.0722f * 3.0f);
  light.info = glm::uvec4(0u, WP_LIGHT_TRIANGLE | (c.doubleSided ? WP_LIGHT_DOUBLE_SIDED : 0u), 0u,
                          WP_INVALID);  // no emissive texture
  return light;
}

// The solid-angle density of direction `d` (unit) from `origin` when points are chosen
// uniformly on the triangle's area, found independently of lights.h by casting a ray
// (Möller-Trumbore, in double): distance^2 / (|cos at the light| * area), 0 on a miss.
// `tolerance` widens the triangle in barycentric terms, for directions that were rounded
// to float after aiming exactly at an edge.
double trianglePdf(const TriangleCase& c, glm::dvec3 origin, glm::dvec3 d, double tolerance = 0) {
  glm::dvec3 e1 = c.v1 - c.v0, e2 = c.v2 - c.v0;
  glm::dvec3 p = glm::cross(d, e2);
  double det = glm::dot(e1, p);
  if (det == 0.0) return 0.0;
  glm::dvec3 s = origin - c.v0;
  double b1 = glm::dot(s, p) / det;
  glm::dvec3 q = glm::cross(s, e1);
  double b2 = glm::dot(d, q) / det;
  double t = glm::dot(e2, q) / det;
  if (b1 < -tolerance || b2 < -tolerance || b1 + b2 > 1.0 + tolerance || t <= 0.0) return 0.0;
  glm::dvec3 n = glm::cross(e1, e2);
  double area = 0.5 * glm::length(n);
  double cosAtLight = std::fabs(glm::dot(n, d)) / glm::length(n);
  return t * t / (cosAtLight * area);
}

// The directions from the shading point that reach the triangle: the cone on its vertices,
// bounded by three planes through the shading point (normals pointing inwards).
std::vector<glm::dvec3> coneOf(const TriangleCase& c) {
  glm::dvec3 v[3] = {c.v0 - c.position, c.v1 - c.position, c.v2 - c.position};
  std::vector<glm::dvec3> normals;
  for (int k = 0; k < 3; ++k) {
    glm::dvec3 n = glm::cross(v[k], v[(k + 1) % 3]);
    normals.push_back(glm::dot(n, v[(k + 2) % 3]) > 0.0 ? n : -n);
  }
  return normals;
}

// The smallest cap holding the vertex directions (about the spherical circumcentre, or the
// middle of the longest edge when that already holds the third vertex), so the grid
// resolves small and thin lights. The whole sphere when that cap is wider than a
// hemisphere, which would not be sure to contain the spherical triangle.
SphereBinning triangleBinning(const TriangleCase& c) {
  glm::dvec3 v[3] = {glm::normalize(c.v0 - c.position), glm::normalize(c.v1 - c.position),
                     glm::normalize(c.v2 - c.position)};
  glm::dvec3 axis = glm::normalize(glm::cross(v[1] - v[0], v[2] - v[0]));
  if (glm::dot(axis, v[0]) < 0.0) axis = -axis;
  double cosMin = glm::dot(axis, v[0]);
  for (int k = 0; k < 3; ++k) {
    glm::dvec3 middle = glm::normalize(v[k] + v[(k + 1) % 3]);
    double cosEdge = glm::dot(middle, v[k]);
    if (glm::dot(middle, v[(k + 2) % 3]) >= cosEdge && cosEdge > cosMin) {
      axis = middle;
      cosMin = cosEdge;
    }
  }
  cosMin -= 0.02 * (1.0 - cosMin);  // a margin, so the edges fall inside the grid
  return SphereBinning(16, 32, axis, cosMin > 0.0 ? cosMin : -1.0);
}

class LightTriangle : public ::testing::TestWithParam<TriangleCase> {};

// Each sample's own pdf, distance and radiance must match independent geometry, and the
// directions as a whole must follow that pdf.
TEST_P(LightTriangle, SamplesFollowTheRayCastPdf) {
  const TriangleCase& c = GetParam();
  gpu::GpuLight light = makeLight(c, 1.0f);
  glm::dvec3 normal = glm::normalize(glm::cross(c.v1 - c.v0, c.v2 - c.v0));
  bool lit = c.doubleSided || glm::dot(normal, c.position - c.v0) > 0.0;
  glm::vec3 expectedRadiance = lit ? glm::vec3(1, 2, 3) : glm::vec3(0);

  TestRandom random(2);
  std::vector<glm::dvec3> directions;
  directions.reserve(kSamples);
  double worstPdfError = 0, worstDistanceError = 0, worstLightPdfError = 0;
  int misses = 0, wrongRadiance = 0;
  for (int i = 0; i < kSamples; ++i) {
    // No emissive texture, so no shading records or textures to pass.
    gpu::LightSample s =
        gpu::sampleLightTriangle(gpu::DeviceBuffers{}, light, glm::vec3(c.position), next2(random));
    glm::dvec3 d = glm::normalize(glm::dvec3(s.direction));
    double reference = trianglePdf(c, c.position, d, 1e-4);
    if (reference == 0.0 || !(s.pdf > 0.0f)) {
      ++misses;
      continue;
    }
    worstPdfError = std::max(worstPdfError, std::fabs(s.pdf / reference - 1.0));
    // The distance along d to the triangle's plane.
    double distance = glm::dot(c.v0 - c.position, normal) / glm::dot(d, normal);
    worstDistanceError = std::max(worstDistanceError, std::fabs(s.distance / distance - 1.0));
    float cosAtLight = float(glm::dot(normal, d));
    float lightPdf = gpu::lightPdf(light, light.edge1.w, s.distance * s.distance, cosAtLight);
    worstLightPdfError = std::max(worstLightPdfError, std::fabs(lightPdf / reference - 1.0));
    if (s.radiance != expectedRadiance) ++wrongRadiance;
    directions.push_back(d);
  }
  // float vs double geometry: relative errors grow like 1e-7 / |cos at the light|.
  EXPECT_EQ(misses, 0);
  EXPECT_LT(worstPdfError, 1e-5);
  EXPECT_LT(worstLightPdfError, 1e-5);
  EXPECT_LT(worstDistanceError, 1e-5);
  EXPECT_EQ(wrongRadiance, 0);

  SphereBinning binning = triangleBinning(c);
  auto pdf = [&](glm::dvec3 d) { return trianglePdf(c, c.position, d); };
  auto result = chiSquareTest(binning.histogram(directions), binning.expectedCounts(pdf, kSamples, 24, coneOf(c)));
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

// lights.h's density (lightPdf, with the selection probability) integrates over the sphere
// to that probability: every direction that reaches the light is counted once.
TEST_P(LightTriangle, LightPdfIntegratesToTheSelectionProbability) {
  const TriangleCase& c = GetParam();
  const float selection = 0.25f;
  gpu::GpuLight light = makeLight(c, selection);
  auto pdf = [&](glm::dvec3 d) {
    double geometric = trianglePdf(c, c.position, d);
    if (geometric == 0.0) return 0.0;
    glm::dvec3 e1 = c.v1 - c.v0, e2 = c.v2 - c.v0, n = glm::normalize(glm::cross(e1, e2));
    double distance = glm::dot(c.v0 - c.position, n) / glm::dot(d, n);
    return double(gpu::lightPdf(light, selection, float(distance * distance), float(glm::dot(n, d))));
  };
  auto cells = triangleBinning(c).expectedCounts(pdf, 1.0, 48, coneOf(c));
  double integral = 0;
  for (double cell : cells) integral += cell;
  EXPECT_NEAR(integral, selection, 1e-4 * selection);
}

INSTANTIATE_TEST_SUITE_P(Shapes, LightTriangle, ::testing::ValuesIn(kTriangleCases),
                         [](const auto& info) { return std::string(info.param.name); });

// ---- Light selection -----------------------------------------------------------------------

// The light table as the buffers lights.h reads (the other buffers stay null: these lights
// have no emissive texture).
gpu::DeviceBuffers lightBuffers(const std::vector<gpu::GpuLight>& lights) {
  gpu::DeviceBuffers buffers{};
  buffers.lights = lights.data();
  return buffers;
}

// A Vose alias table in GpuLight's fields (edge1.w: probability, edge2.w: threshold, info.x:
// alias), written here independently of the scene packer that builds the real one.
std::vector<gpu::GpuLight> aliasTable(const std::vector<double>& weights) {
  size_t n = weights.size();
  double total = 0;
  for (double w : weights) total += w;
  std::vector<gpu::GpuLight> lights(n);
  std::vector<double> scaled(n);
  std::vector<size_t> small, large;
  for (size_t i = 0; i < n; ++i) {
    lights[i] = gpu::GpuLight{};
    lights[i].edge1.w = float(weights[i] / total);
    lights[i].edge2.w = 1.0f;
    lights[i].info.x = uint32_t(i);  // leftovers alias themselves, so rounding cannot leak
    scaled[i] = weights[i] / total * double(n);
    (scaled[i] < 1.0 ? small : large).push_back(i);
  }
  while (!small.empty() && !large.empty()) {
    size_t s = small.back(), l = large.back();
    small.pop_back();
    large.pop_back();
    lights[s].edge2.w = float(scaled[s]);
    lights[s].info.x = uint32_t(l);
    scaled[l] -= 1.0 - scaled[s];
    (scaled[l] < 1.0 ? small : large).push_back(l);
  }
  return lights;
}

std::vector<double> probabilitiesOf(const std::vector<gpu::GpuLight>& lights) {
  std::vector<double> p;
  for (const auto& light : lights) p.push_back(light.edge1.w);
  return p;
}

class AliasTable : public ::testing::TestWithParam<std::vector<double>> {};

TEST_P(AliasTable, TableEncodesTheProbabilities) {
  auto lights = aliasTable(GetParam());
  size_t n = lights.size();
  std::vector<double> encoded(n, 0.0);
  for (size_t i = 0; i < n; ++i) {
    encoded[i] += lights[i].edge2.w / double(n);
    encoded[lights[i].info.x] += (1.0 - lights[i].edge2.w) / double(n);
  }
  auto p = probabilitiesOf(lights);
  for (size_t i = 0; i < n; ++i) EXPECT_NEAR(encoded[i], p[i], 1e-6) << "light " << i;
}

TEST_P(AliasTable, SelectLightFollowsTheProbabilities) {
  auto lights = aliasTable(GetParam());
  auto n = uint32_t(lights.size());
  std::vector<double> observed(n, 0.0), expected;
  TestRandom random(3);
  for (int i = 0; i < kSamples; ++i) {
    uint32_t index = gpu::selectLight(lightBuffers(lights), n, random.next());
    ASSERT_LT(index, n);
    observed[index] += 1.0;
  }
  for (double p : probabilitiesOf(lights)) expected.push_back(p * kSamples);
  auto result = chiSquareTest(observed, expected);
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

std::vector<double> manyUnevenWeights() {
  std::vector<double> w;
  for (int i = 0; i < 37; ++i) w.push_back((i == 10 || i == 20) ? 0.0 : std::exp(-i / 5.0) * (1 + i % 3));
  return w;
}

// Both tables hold lights of probability 0, which must never be chosen.
INSTANTIATE_TEST_SUITE_P(Weights, AliasTable,
                         ::testing::Values(std::vector<double>{0.5, 0.05, 0.0, 0.2, 0.15, 0.1},
                                           manyUnevenWeights()));

TEST(SampleLight, MultipliesSelectionAndTriangleDensities) {
  std::vector<gpu::GpuLight> lights = aliasTable({1.0, 3.0, 0.5});
  for (size_t i = 0; i < lights.size(); ++i) {
    gpu::GpuLight withGeometry = makeLight(kTriangleCases[i], lights[i].edge1.w);
    withGeometry.edge2.w = lights[i].edge2.w;
    withGeometry.info.x = lights[i].info.x;
    lights[i] = withGeometry;
  }
  TestRandom random(4);
  glm::vec3 position(0.1f, 0.0f, 0.2f);
  for (int i = 0; i < 1000; ++i) {
    glm::vec3 u(random.next(), random.next(), random.next());
    gpu::LightSample s =
        gpu::sampleLight(lightBuffers(lights), 3, WP_LIGHT_SELECTION_POWER, position, 0.0f, u);
    const gpu::GpuLight& chosen = lights[gpu::selectLight(lightBuffers(lights), 3, u.x)];
    gpu::LightSample alone = gpu::sampleLightTriangle(gpu::DeviceBuffers{}, chosen, position, glm::vec2(u.y, u.z));
    ASSERT_EQ(s.direction, alone.direction);
    ASSERT_FLOAT_EQ(s.pdf, alone.pdf * chosen.edge1.w);
  }
}

// The eight faces of an octahedron about any point inside it cover the whole sphere, so
// their solid angles sum to 4 pi; seen from near a face, that face spans more than a
// hemisphere's half (the branch where the formula's denominator is negative). From the
// centre each face is an octant, pi / 2.
TEST(SolidAngle, OctahedronFacesSumToTheSphere) {
  const double kPi = 3.14159265358979323846;
  for (glm::vec3 p : {glm::vec3(0.0f), glm::vec3(0.3f, 0.3f, 0.3f), glm::vec3(0.1f, -0.2f, 0.5f)}) {
    double sum = 0.0;
    for (int octant = 0; octant < 8; ++octant) {
      glm::vec3 sign(octant & 1 ? -1.0f : 1.0f, octant & 2 ? -1.0f : 1.0f, octant & 4 ? -1.0f : 1.0f);
      float omega = gpu::triangleSolidAngle(glm::vec3(sign.x, 0, 0) - p, glm::vec3(0, sign.y, 0) - p,
                                            glm::vec3(0, 0, sign.z) - p);
      if (p == glm::vec3(0.0f)) {
        EXPECT_NEAR(omega, kPi / 2.0, 1e-5);
      }
      sum += omega;
    }
    EXPECT_NEAR(sum, 4.0 * kPi, 1e-4) << p.x << " " << p.y << " " << p.z;
  }
}

// Selection by solid angle: each light is chosen as often as its weight says (chi-square),
// a one-sided light seen from behind never, and sampleLight's pdf includes the selection
// probability that the MIS weight at a light hit recomputes.
TEST(SampleLight, SolidAngleSelectionFollowsTheWeights) {
  std::vector<gpu::GpuLight> lights;
  for (int i = 0; i < 3; ++i) lights.push_back(makeLight(kTriangleCases[i], 0.0f));
  lights[2].info.y = WP_LIGHT_TRIANGLE | WP_LIGHT_DOUBLE_SIDED;  // LargeAndClose: lit from below as well
  glm::vec3 position(0.1f, 0.0f, 0.2f);
  std::vector<double> expected;
  double sum = gpu::solidAngleWeightSum(lightBuffers(lights), 3, position, 0.0f);
  const int kCount = 100000;
  for (const gpu::GpuLight& light : lights) expected.push_back(kCount * gpu::solidAngleWeight(light, position, 0.0f) / sum);
  EXPECT_EQ(expected[0], 0.0);  // "Facing" shows this point its back: cross(e1, e2) points away
  std::vector<double> observed(3, 0.0);
  TestRandom random(5);
  for (int i = 0; i < kCount; ++i) {
    glm::vec3 u(random.next(), random.next(), random.next());
    gpu::LightChoice choice = gpu::selectLightBySolidAngle(lightBuffers(lights), 3, position, 0.0f, u.x);
    ASSERT_LT(choice.index, 3u);
    observed[choice.index] += 1.0;
    float probability = gpu::lightSelectionProbability(lightBuffers(lights), 3, WP_LIGHT_SELECTION_SOLID_ANGLE,
                                                       lights[choice.index], position, 0.0f);
    ASSERT_FLOAT_EQ(choice.probability, probability);
    gpu::LightSample s =
        gpu::sampleLight(lightBuffers(lights), 3, WP_LIGHT_SELECTION_SOLID_ANGLE, position, 0.0f, u);
    gpu::LightSample alone =
        gpu::sampleLightTriangle(gpu::DeviceBuffers{}, lights[choice.index], position, glm::vec2(u.y, u.z));
    ASSERT_EQ(s.direction, alone.direction);
    ASSERT_FLOAT_EQ(s.pdf, alone.pdf * probability);
  }
  EXPECT_EQ(observed[0], 0.0);
  std::vector<double> o = {observed[1], observed[2]}, e = {expected[1], expected[2]};
  auto result = chiSquareTest(o, e);
  EXPECT_TRUE(result.accepts(0.01)) << result.describe();
}

// ---- Random numbers ------------------------------------------------------------------------

const uint32_t kRenderSeed = 20240607u;

// Chi-square test of points against the uniform density on [0, 1)^2 over a bins x bins
// grid; any point outside [0, 1)^2 fails the test.
wp::test::ChiSquareResult uniformityOf(const std::vector<glm::vec2>& points, int bins) {
  std::vector<double> observed(bins * bins, 0.0);
  int outside = 0;
  for (glm::vec2 p : points) {
    if (p.x >= 0.0f && p.x < 1.0f && p.y >= 0.0f && p.y < 1.0f)
      observed[int(p.y * bins) * bins + int(p.x * bins)] += 1.0;
    else
      ++outside;
  }
  EXPECT_EQ(outside, 0);
  std::vector<double> expected(observed.size(), double(points.size()) / observed.size());
  return chiSquareTest(observed, expected);
}

// The first number a path draws, as generate.comp does: seed, advance, read.
float firstDraw(uint32_t pixel, uint32_t sample) {
  return gpu::rngFloat(gpu::rngNext(gpu::rngSeed(pixel, sample, kRenderSeed)));
}

TEST(Rng, FloatsAreUniformOnTheUnitInterval) {
  uint32_t state = gpu::rngSeed(0, 0, kRenderSeed);
  std::vector<double> observed(64, 0.0);
  int outside = 0;
  for (int i = 0; i < kSamples; ++i) {
    state = gpu::rngNext(state);
    float u = gpu::rngFloat(state);
    if (!(u >= 0.0f && u < 1.0f)) {
      ++outside;
      continue;
    }
    observed[int(u * 64)] += 1.0;
  }
  EXPECT_EQ(outside, 0);
  auto result = chiSquareTest(observed, std::vector<double>(64, kSamples / 64.0));
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

// Non-overlapping pairs, so the cells are independent as the chi-square test assumes.
TEST(Rng, ConsecutiveFloatsAreIndependent) {
  uint32_t state = gpu::rngSeed(1, 0, kRenderSeed);
  std::vector<glm::vec2> pairs;
  for (int i = 0; i < kSamples; ++i) {
    state = gpu::rngNext(state);
    float x = gpu::rngFloat(state);
    state = gpu::rngNext(state);
    pairs.emplace_back(x, gpu::rngFloat(state));
  }
  auto result = uniformityOf(pairs, 32);
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

TEST(Rng, NeighbouringPixelsAreIndependent) {
  std::vector<glm::vec2> pairs;
  for (uint32_t p = 0; p < 2u * kSamples; p += 2) pairs.emplace_back(firstDraw(p, 0), firstDraw(p + 1, 0));
  auto result = uniformityOf(pairs, 32);
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

TEST(Rng, SuccessiveSamplesOfAPixelAreIndependent) {
  std::vector<glm::vec2> pairs;
  for (uint32_t s = 0; s < 2u * kSamples; s += 2) pairs.emplace_back(firstDraw(4321, s), firstDraw(4321, s + 1));
  auto result = uniformityOf(pairs, 32);
  EXPECT_TRUE(result.accepts(kAlpha)) << result.describe();
}

}  // namespace
