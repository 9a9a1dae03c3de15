// Chi-square p-values (incomplete gamma, after Numerical Recipes §6.2), pooling, sphere bins.
#include "support/chi_square.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>

namespace wp::test {
namespace {

constexpr double kTwoPi = 6.283185307179586;
constexpr double kEpsilon = 1e-15;
constexpr int kMaxIterations = 1000000;
// Absolute error allowed per row of a cell (in probability), and the deepest subdivision.
constexpr double kSimpsonTolerance = 1e-10;
constexpr int kSimpsonDepth = 12;

// exp(-x) x^a / Gamma(a): the factor shared by the series and the continued fraction.
double gammaPrefactor(double a, double x) { return std::exp(-x + a * std::log(x) - std::lgamma(a)); }

// Regularized lower incomplete gamma P(a, x) by its power series; converges fast for x < a + 1.
double gammaPSeries(double a, double x) {
  double term = 1.0 / a, sum = term;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::fabs(term) < std::fabs(sum) * kEpsilon) return sum * gammaPrefactor(a, x);
  }
  throw std::runtime_error("gammaPSeries did not converge");
}

// Regularized upper incomplete gamma Q(a, x) by its continued fraction (modified Lentz);
// converges fast for x >= a + 1.
double gammaQContinuedFraction(double a, double x) {
  const double tiny = std::numeric_limits<double>::min() / kEpsilon;
  double b = x + 1.0 - a, c = 1.0 / tiny, d = 1.0 / b, h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::fabs(d) < tiny) d = tiny;
    c = b + an / c;
    if (std::fabs(c) < tiny) c = tiny;
    d = 1.0 / d;
    double delta = d * c;
    h *= delta;
    if (std::fabs(delta - 1.0) < kEpsilon) return h * gammaPrefactor(a, x);
  }
  throw std::runtime_error("gammaQContinuedFraction did not converge");
}

double regularizedGammaQ(double a, double x) {
  if (x <= 0.0) return 1.0;
  return x < a + 1.0 ? 1.0 - gammaPSeries(a, x) : gammaQContinuedFraction(a, x);
}

}  // namespace

double chiSquarePValue(double statistic, int degreesOfFreedom) {
  if (degreesOfFreedom < 1) throw std::invalid_argument("chiSquarePValue needs at least one degree of freedom");
  if (std::isnan(statistic)) return statistic;
  return regularizedGammaQ(0.5 * degreesOfFreedom, 0.5 * statistic);
}

double sidakAlpha(double alpha, int testCount) { return 1.0 - std::pow(1.0 - alpha, 1.0 / testCount); }

std::string ChiSquareResult::describe() const {
  std::ostringstream out;
  out << "chi2 = " << statistic << ", dof = " << degreesOfFreedom << ", p = " << pValue
      << ", pooled cells = " << pooledCells;
  if (!failure.empty()) out << ", failure: " << failure;
  return out.str();
}

ChiSquareResult chiSquareTest(const std::vector<double>& observed, const std::vector<double>& expected,
                              double minExpected) {
  if (observed.size() != expected.size()) throw std::invalid_argument("chiSquareTest: cell counts differ");
  ChiSquareResult result;
  std::vector<size_t> order(expected.size());
  std::iota(order.begin(), order.end(), size_t(0));
  std::sort(order.begin(), order.end(), [&](size_t a, size_t b) { return expected[a] < expected[b]; });

  double pooledObserved = 0, pooledExpected = 0;
  int cells = 0;
  for (size_t i : order) {
    double o = observed[i], e = expected[i];
    if (e == 0.0) {
      if (o > 0.0 && result.failure.empty())
        result.failure = std::to_string(o) + " samples in cell " + std::to_string(i) + ", which expects none";
      continue;
    }
    if (e < minExpected || (result.pooledCells > 0 && pooledExpected < minExpected)) {
      pooledObserved += o;
      pooledExpected += e;
      ++result.pooledCells;
    } else {
      result.statistic += (o - e) * (o - e) / e;
      ++cells;
    }
  }
  if (result.pooledCells > 0) {
    result.statistic += (pooledObserved - pooledExpected) * (pooledObserved - pooledExpected) / pooledExpected;
    ++cells;
  }
  result.degreesOfFreedom = cells - 1;
  if (result.degreesOfFreedom < 1) {
    if (result.failure.empty()) result.failure = "fewer than two cells to compare; use more samples or cells";
    return result;
  }
  result.pValue = chiSquarePValue(result.statistic, result.degreesOfFreedom);
  return result;
}

SphereBinning::SphereBinning(int cosThetaBins, int phiBins, glm::dvec3 axis, double cosThetaMin)
    : cosThetaBins_(cosThetaBins), phiBins_(phiBins), cosThetaMin_(cosThetaMin), axis_(glm::normalize(axis)) {
  if (cosThetaBins < 1 || phiBins < 1 || !(cosThetaMin >= -1.0 && cosThetaMin < 1.0))
    throw std::invalid_argument("SphereBinning: bad grid");
  // For the z axis this gives the usual phi, measured from x towards y.
  glm::dvec3 helper = std::fabs(axis_.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(1, 0, 0);
  tangent_ = glm::normalize(glm::cross(helper, axis_));
  bitangent_ = glm::cross(axis_, tangent_);
}

int SphereBinning::cellCount() const { return cosThetaBins_ * phiBins_ + (cosThetaMin_ > -1.0 ? 1 : 0); }

int SphereBinning::cellOf(glm::dvec3 direction) const {
  glm::dvec3 d = glm::normalize(direction);
  double cosTheta = std::clamp(glm::dot(d, axis_), -1.0, 1.0);
  if (cosTheta < cosThetaMin_) return cosThetaBins_ * phiBins_;
  double phi = std::atan2(glm::dot(d, bitangent_), glm::dot(d, tangent_));
  if (phi < 0.0) phi += kTwoPi;
  int row = std::min(int((cosTheta - cosThetaMin_) / (1.0 - cosThetaMin_) * cosThetaBins_), cosThetaBins_ - 1);
  int column = std::min(int(phi / kTwoPi * phiBins_), phiBins_ - 1);
  return row * phiBins_ + column;
}

std::vector<double> SphereBinning::histogram(const std::vector<glm::dvec3>& directions) const {
  std::vector<double> counts(cellCount(), 0.0);
  for (const glm::dvec3& d : directions) counts[cellOf(d)] += 1.0;
  return counts;
}

std::vector<std::pair<double, double>> SphereBinning::supportArcs(double cosTheta, double phi0, double phi1,
                                                                  const std::vector<glm::dvec3>& support) const {
  // On the circle of constant cos(theta), dot(d, h) = r cos(phi - phiH) + c, so each
  // half-space keeps one arc of phi, which is intersected with what is left.
  double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  std::vector<std::pair<double, double>> arcs = {{phi0, phi1}};
  for (glm::dvec3 h : support) {
    double ht = glm::dot(h, tangent_), hb = glm::dot(h, bitangent_);
    double r = sinTheta * std::sqrt(ht * ht + hb * hb), c = cosTheta * glm::dot(h, axis_);
    if (r <= std::fabs(c)) {
      if (c < 0.0) arcs.clear();
      continue;
    }
    double halfWidth = std::acos(std::clamp(-c / r, -1.0, 1.0)), center = std::atan2(hb, ht);
    std::vector<std::pair<double, double>> kept;
    for (auto [lo, hi] : arcs)
      for (int k = -1; k <= 1; ++k) {
        double a = std::max(lo, center - halfWidth + k * kTwoPi),
               b = std::min(hi, center + halfWidth + k * kTwoPi);
        if (a < b) kept.emplace_back(a, b);
      }
    arcs = std::move(kept);
  }
  return arcs;
}

double SphereBinning::ring(const Integrand& f, double cosTheta, double phi0, double phi1) const {
  double sinTheta = std::sqrt(std::max(0.0, 1.0 - cosTheta * cosTheta));
  double sum = 0.0;
  for (auto [lo, hi] : supportArcs(cosTheta, phi0, phi1, f.support)) {
    double step = (hi - lo) / f.resolution;
    for (int j = 0; j < f.resolution; ++j) {
      double phi = lo + (j + 0.5) * step;
      sum += f.pdf(sinTheta * (std::cos(phi) * tangent_ + std::sin(phi) * bitangent_) + cosTheta * axis_) * step;
    }
  }
  return sum;
}

double SphereBinning::adaptiveSimpson(const Integrand& f, double phi0, double phi1, double a, double b, double fa,
                                      double fm, double fb, double whole, double tolerance, int depth) const {
  double m = 0.5 * (a + b);
  double flm = thetaIntegrand(f, 0.5 * (a + m), phi0, phi1), frm = thetaIntegrand(f, 0.5 * (m + b), phi0, phi1);
  double left = (m - a) / 6.0 * (fa + 4.0 * flm + fm), right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
  double delta = left + right - whole;
  if (depth == 0 || std::fabs(delta) <= 15.0 * tolerance) return left + right + delta / 15.0;
  return adaptiveSimpson(f, phi0, phi1, a, m, fa, flm, fm, left, 0.5 * tolerance, depth - 1) +
         adaptiveSimpson(f, phi0, phi1, m, b, fm, frm, fb, right, 0.5 * tolerance, depth - 1);
}

double SphereBinning::thetaIntegrand(const Integrand& f, double theta, double phi0, double phi1) const {
  return ring(f, std::cos(theta), phi0, phi1) * std::sin(theta);
}

double SphereBinning::integrate(const Integrand& f, double cosTheta0, double cosTheta1, double phi0,
                                double phi1) const {
  // Integrated over theta rather than cos(theta), whose steps shrink to nothing in angle at
  // the poles: a light corner or sliver at the pole of the grid would fall between them.
  double theta0 = std::acos(std::clamp(cosTheta1, -1.0, 1.0)),
         theta1 = std::acos(std::clamp(cosTheta0, -1.0, 1.0));
  double step = (theta1 - theta0) / f.resolution;
  double sum = 0.0;
  for (int i = 0; i < f.resolution; ++i) {
    double a = theta0 + i * step, b = a + step;
    double fa = thetaIntegrand(f, a, phi0, phi1), fm = thetaIntegrand(f, 0.5 * (a + b), phi0, phi1);
    double fb = thetaIntegrand(f, b, phi0, phi1);
    double whole = step / 6.0 * (fa + 4.0 * fm + fb);
    sum += adaptiveSimpson(f, phi0, phi1, a, b, fa, fm, fb, whole, kSimpsonTolerance, kSimpsonDepth);
  }
  return sum;
}

std::vector<double> SphereBinning::expectedCounts(const std::function<double(glm::dvec3)>& pdf, double sampleCount,
                                                  int resolution, const std::vector<glm::dvec3>& support) const {
  Integrand f{pdf, resolution, support};
  double cellHeight = (1.0 - cosThetaMin_) / cosThetaBins_, cellWidth = kTwoPi / phiBins_;
  std::vector<double> counts(cellCount(), 0.0);
  for (int row = 0; row < cosThetaBins_; ++row)
    for (int column = 0; column < phiBins_; ++column) {
      double cosTheta0 = cosThetaMin_ + row * cellHeight, phi0 = column * cellWidth;
      counts[row * phiBins_ + column] =
          sampleCount * integrate(f, cosTheta0, cosTheta0 + cellHeight, phi0, phi0 + cellWidth);
    }
  // The outside of a cap is integrated on a grid as fine as the inside, so a pdf that is 0
  // there expects exactly 0 samples.
  if (cosThetaMin_ > -1.0) {
    double outsideHeight = (cosThetaMin_ + 1.0) / cosThetaBins_;
    for (int row = 0; row < cosThetaBins_; ++row)
      for (int column = 0; column < phiBins_; ++column) {
        double cosTheta0 = -1.0 + row * outsideHeight, phi0 = column * cellWidth;
        counts.back() += sampleCount * integrate(f, cosTheta0, cosTheta0 + outsideHeight, phi0, phi0 + cellWidth);
      }
  }
  return counts;
}

}  // namespace wp::test
