// Pearson's chi-square goodness-of-fit test, and sphere binning to apply it to direction
// samplers (after Mitsuba 3's chi2 tests: histogram of samples vs. the integrated pdf).
#pragma once

#include <cstdint>
#include <functional>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

namespace wp::test {

// P(X >= statistic) for X chi-square distributed with `degreesOfFreedom` (>= 1): the
// regularized upper incomplete gamma function Q(dof / 2, statistic / 2).
double chiSquarePValue(double statistic, int degreesOfFreedom);

// Per-test significance level that keeps the chance of any false rejection among
// `testCount` independent tests at `alpha` (Šidák: 1 - (1 - alpha)^(1 / testCount)).
double sidakAlpha(double alpha, int testCount);

struct ChiSquareResult {
  double statistic = 0;
  int degreesOfFreedom = 0;
  double pValue = 0;
  int pooledCells = 0;  // cells merged into one because their expected counts were small
  std::string failure;  // set when the data reject the hypothesis whatever the p-value

  // True when the hypothesis survives at significance level alpha.
  bool accepts(double alpha) const { return failure.empty() && pValue > alpha; }
  std::string describe() const;
};

// Compares observed counts with expected counts per cell. Cells expecting fewer than
// `minExpected` samples are pooled (smallest first) until the pool expects at least that
// many, because the chi-square approximation needs them; cells expecting and holding
// nothing are ignored. Any sample in a cell expecting exactly 0 is a failure, as are fewer
// than two cells left (no degree of freedom).
ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected = 5);

// Cells over unit directions: cosThetaBins x phiBins cells of equal solid angle in
// (cos theta, phi) about `axis`, covering the cap cos(theta) >= cosThetaMin (-1: the whole
// sphere). A cap that is not the whole sphere gets one more cell, the last, for everything
// outside it, so a sampler that leaves the cap is caught. Narrow caps put resolution where
// a small light's directions are.
class SphereBinning {
public:
  explicit SphereBinning(int cosThetaBins = 10, int phiBins = 20, glm::dvec3 axis = {0, 0, 1},
                         double cosThetaMin = -1);

  int cellCount() const;
  int cellOf(glm::dvec3 direction) const;

  // Counts of `directions` per cell.
  std::vector<double> histogram(const std::vector<glm::dvec3>& directions) const;

  // sampleCount times the integral of `pdf` (over solid angle) across each cell. Each cell
  // is cut into `resolution` rows of theta; along each circle of constant theta the
  // midpoint rule takes `resolution` points of phi, and across theta adaptive Simpson
  // refines wherever that ring integral bends, e.g. at a light's corner. The outside of a
  // cap is integrated the same way. A pdf that drops to 0 across great circles, as the
  // density of a hemisphere or of a light triangle does, passes their normals h as
  // `support` (the pdf is 0 unless dot(d, h) >= 0 for every h): each ring then covers
  // exactly the part inside the support, so thin slivers and edges count fully instead of
  // falling between points.
  std::vector<double> expectedCounts(const std::function<double(glm::dvec3)>& pdf, double sampleCount,
                                     int resolution = 16, const std::vector<glm::dvec3>& support = {}) const;

private:
  struct Integrand {
    const std::function<double(glm::dvec3)>& pdf;
    int resolution;
    const std::vector<glm::dvec3>& support;
  };
  // The intervals of phi within [phi0, phi1] inside the support on the circle cos(theta).
  std::vector<std::pair<double, double>> supportArcs(double cosTheta, double phi0, double phi1,
                                                     const std::vector<glm::dvec3>& support) const;
  // The integral of the pdf over phi in [phi0, phi1] on the circle cos(theta).
  double ring(const Integrand& f, double cosTheta, double phi0, double phi1) const;
  // ring() * sin(theta): the integrand over theta, as solid angle is sin(theta) dtheta dphi.
  double thetaIntegrand(const Integrand& f, double theta, double phi0, double phi1) const;
  double adaptiveSimpson(const Integrand& f, double phi0, double phi1, double a, double b, double fa, double fm,
                         double fb, double whole, double tolerance, int depth) const;
  double integrate(const Integrand& f, double cosTheta0, double cosTheta1, double phi0, double phi1) const;

  int cosThetaBins_, phiBins_;
  double cosThetaMin_;
  glm::dvec3 tangent_, bitangent_, axis_;
};

// Uniform floats in [0, 1) with 24 random bits, like the GPU's rngFloat, from a fixed-seed
// Mersenne Twister: deterministic and independent of the RNG under test. (The standard
// distributions are not used because their output differs between library vendors.)
class TestRandom {
public:
  explicit TestRandom(uint64_t seed) : engine_(seed) {}
  float next() { return float(engine_() >> 40) * 0x1p-24f; }

private:
  std::mt19937_64 engine_;
};

}  // namespace wp::test
