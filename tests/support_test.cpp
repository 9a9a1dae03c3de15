// Tests of the chi-square machinery itself: p-values against known values, pooling, and that
// it rejects a sampler paired with the wrong pdf while accepting the right one.
#include <gtest/gtest.h>

#include <cmath>

#include "support/chi_square.h"

namespace {

using wp::test::chiSquarePValue;
using wp::test::chiSquareTest;
using wp::test::SphereBinning;
using wp::test::TestRandom;

constexpr double kPi = 3.14159265358979323846;

TEST(ChiSquarePValue, MatchesTabulatedCriticalValues) {
  // Critical values from standard chi-square tables.
  EXPECT_NEAR(chiSquarePValue(3.841459, 1), 0.05, 1e-6);
  EXPECT_NEAR(chiSquarePValue(6.634897, 1), 0.01, 1e-6);
  EXPECT_NEAR(chiSquarePValue(18.307038, 10), 0.05, 1e-6);
  EXPECT_NEAR(chiSquarePValue(23.209251, 10), 0.01, 1e-6);
  EXPECT_NEAR(chiSquarePValue(124.342113, 100), 0.05, 1e-6);
}

// Closed forms: Q = exp(-x/2) for 2 dof, erfc(sqrt(x/2)) for 1 dof and
// erfc(sqrt(x/2)) + sqrt(2x/pi) exp(-x/2) for 3 dof, across both numerical branches.
TEST(ChiSquarePValue, MatchesClosedFormsForSmallDegreesOfFreedom) {
  for (double x : {0.01, 0.5, 1.0, 2.0, 2.9, 3.1, 5.0, 10.0, 30.0, 80.0}) {
    EXPECT_NEAR(chiSquarePValue(x, 2), std::exp(-x / 2), 1e-12) << x;
    EXPECT_NEAR(chiSquarePValue(x, 1), std::erfc(std::sqrt(x / 2)), 1e-12) << x;
    double three = std::erfc(std::sqrt(x / 2)) + std::sqrt(2 * x / kPi) * std::exp(-x / 2);
    EXPECT_NEAR(chiSquarePValue(x, 3), three, 1e-12) << x;
  }
  EXPECT_EQ(chiSquarePValue(0.0, 5), 1.0);
}

TEST(ChiSquarePValue, IsNearOneHalfAtTheMeanForManyDegreesOfFreedom) {
  // The distribution is slightly right-skewed, so P(X >= mean) is a little below 1/2
  // (Wilson-Hilferty: 0.4981 for 10000 dof).
  double p = chiSquarePValue(10000.0, 10000);
  EXPECT_GT(p, 0.495);
  EXPECT_LT(p, 0.5);
}

TEST(SidakAlpha, KeepsTheFamilyWiseErrorRate) {
  EXPECT_NEAR(wp::test::sidakAlpha(0.01, 1), 0.01, 1e-15);
  double perTest = wp::test::sidakAlpha(0.01, 12);
  EXPECT_NEAR(1.0 - std::pow(1.0 - perTest, 12), 0.01, 1e-12);
  EXPECT_LT(perTest, 0.01 / 12 * 1.01);
}

TEST(ChiSquareTest, AcceptsExactCountsAndReportsDegreesOfFreedom) {
  std::vector<double> counts = {10, 20, 30, 40};
  auto result = chiSquareTest(counts, counts);
  EXPECT_EQ(result.statistic, 0.0);
  EXPECT_EQ(result.degreesOfFreedom, 3);
  EXPECT_EQ(result.pValue, 1.0);
  EXPECT_TRUE(result.accepts(0.01)) << result.describe();
}

TEST(ChiSquareTest, PoolsSmallCellsUntilThePoolIsLargeEnough) {
  // Five cells expecting 1 each pool into one expecting 5; two large cells stay: 3 cells.
  std::vector<double> expected = {1, 100, 1, 1, 100, 1, 1};
  std::vector<double> observed = {0, 104, 2, 1, 96, 0, 2};
  auto result = chiSquareTest(observed, expected);
  EXPECT_EQ(result.pooledCells, 5);
  EXPECT_EQ(result.degreesOfFreedom, 2);
  EXPECT_NEAR(result.statistic, 0.16 + 0.16 + 0.0, 1e-12);
}

TEST(ChiSquareTest, FailsOnSamplesWhereNoneAreExpected) {
  std::vector<double> expected = {0, 50, 50};
  auto result = chiSquareTest({1, 50, 49}, expected);
  EXPECT_FALSE(result.failure.empty());
  EXPECT_FALSE(result.accepts(0.01));
  EXPECT_TRUE(chiSquareTest({0, 50, 50}, expected).accepts(0.01));
}

TEST(ChiSquareTest, FailsWithoutDegreesOfFreedom) {
  auto result = chiSquareTest({100}, {100});
  EXPECT_FALSE(result.failure.empty());
  EXPECT_FALSE(result.accepts(0.01));
}

TEST(SphereBinning, UniformPdfFillsEqualAreaCellsEqually) {
  SphereBinning binning(10, 20);
  auto expected = binning.expectedCounts([](glm::dvec3) { return 1.0 / (4 * kPi); }, 2000.0, 4);
  ASSERT_EQ(expected.size(), 200u);
  for (double e : expected) EXPECT_NEAR(e, 10.0, 1e-9);
  EXPECT_EQ(binning.cellOf({0, 0, 1}), 199 - 19);  // top row, phi = 0
  EXPECT_EQ(binning.cellOf({0, 0, -1}), 0);
  EXPECT_EQ(binning.cellOf({0, -1, 0}), 5 * 20 + 15);  // cos theta = 0, phi = 3 pi / 2
}

TEST(SphereBinning, CapSendsOutsideDirectionsToTheLastCell) {
  SphereBinning cap(4, 8, {1, 0, 0}, 0.5);
  EXPECT_EQ(cap.cellCount(), 33);
  EXPECT_EQ(cap.cellOf({0, 0, 1}), 32);
  EXPECT_EQ(cap.cellOf({-1, 0, 0}), 32);
  EXPECT_LT(cap.cellOf({1, 0.1, 0}), 32);
  // A uniform pdf puts (1 - 0.5) / 2 of the sphere inside the cap, 3/4 outside.
  auto expected = cap.expectedCounts([](glm::dvec3) { return 1.0 / (4 * kPi); }, 1.0, 4);
  EXPECT_NEAR(expected.back(), 0.75, 1e-9);
}

// With the support given, a density with sharp edges inside cells (here the lune
// a <= phi <= b, whose share of each cell is known exactly) integrates exactly per cell;
// without it the cells cut by an edge are off by up to an eighth of their content.
TEST(SphereBinning, SupportMakesSharpEdgesExact) {
  const double a = 0.1, b = 1.0, width = 2 * kPi / 20;
  glm::dvec3 afterA(-std::sin(a), std::cos(a), 0), beforeB(std::sin(b), -std::cos(b), 0);
  auto lune = [&](glm::dvec3 d) { return glm::dot(d, afterA) >= 0 && glm::dot(d, beforeB) >= 0 ? 1.0 : 0.0; };
  SphereBinning binning(7, 20);
  auto withSupport = binning.expectedCounts(lune, 1.0, 4, {afterA, beforeB});
  auto without = binning.expectedCounts(lune, 1.0, 4);
  double worstWith = 0, worstWithout = 0;
  for (int row = 0; row < 7; ++row)
    for (int column = 0; column < 20; ++column) {
      double overlap = std::max(0.0, std::min(b, (column + 1) * width) - std::max(a, column * width));
      double exact = overlap * 2.0 / 7.0;
      worstWith = std::max(worstWith, std::fabs(withSupport[row * 20 + column] - exact));
      worstWithout = std::max(worstWithout, std::fabs(without[row * 20 + column] - exact));
    }
  EXPECT_LT(worstWith, 1e-9);
  EXPECT_GT(worstWithout, 1e-3);
}

// Direction uniform on the +z hemisphere: a correct sampler for a pdf this test does not
// claim, so a working chi-square test must reject it against the cosine density.
glm::dvec3 sampleUniformHemisphere(float u1, float u2) {
  double z = u1, r = std::sqrt(std::max(0.0, 1.0 - z * z)), phi = 2 * kPi * u2;
  return {r * std::cos(phi), r * std::sin(phi), z};
}

std::vector<double> uniformHemisphereHistogram(const SphereBinning& binning, int sampleCount) {
  TestRandom random(7);
  std::vector<glm::dvec3> directions;
  for (int i = 0; i < sampleCount; ++i) {
    float u1 = random.next();
    directions.push_back(sampleUniformHemisphere(u1, random.next()));
  }
  return binning.histogram(directions);
}

TEST(ChiSquareTest, RejectsUniformHemisphereSamplesAgainstTheCosinePdf) {
  const int n = 200000;
  SphereBinning binning;
  auto observed = uniformHemisphereHistogram(binning, n);
  auto cosinePdf = [](glm::dvec3 d) { return std::max(d.z, 0.0) / kPi; };
  auto result = chiSquareTest(observed, binning.expectedCounts(cosinePdf, n));
  EXPECT_FALSE(result.accepts(0.01)) << result.describe();
  EXPECT_LT(result.pValue, 1e-12) << result.describe();
}

TEST(ChiSquareTest, AcceptsUniformHemisphereSamplesAgainstTheUniformPdf) {
  const int n = 200000;
  SphereBinning binning;
  auto observed = uniformHemisphereHistogram(binning, n);
  auto uniformPdf = [](glm::dvec3 d) { return d.z >= 0.0 ? 1.0 / (2 * kPi) : 0.0; };
  auto result = chiSquareTest(observed, binning.expectedCounts(uniformPdf, n));
  EXPECT_TRUE(result.accepts(0.01)) << result.describe();
}

}  // namespace
