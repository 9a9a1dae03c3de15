// Image means with their standard errors, and the z statistic that compares two of them.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "image/image_io.h"

namespace wp::test {

// Mean radiance over the image and its standard error. Pixels are independent, so the
// variance of the mean is the sum of the per-pixel variances (the EXR's variance AOV)
// divided by the squared pixel count.
struct ImageMean {
  glm::dvec3 mean{0.0};
  glm::dvec3 standardError{0.0};
};

inline ImageMean imageMean(const RadianceImage& image) {
  ImageMean m;
  glm::dvec3 varianceSum(0.0);
  for (size_t i = 0; i < image.mean.size(); ++i) {
    m.mean += glm::dvec3(image.mean[i]);
    varianceSum += glm::dvec3(image.variance[i]);
  }
  double n = double(image.mean.size());
  m.mean /= n;
  m.standardError = glm::sqrt(varianceSum) / n;
  return m;
}

// Standard error of the difference of two independent means, in channel c.
inline double differenceError(const ImageMean& a, const ImageMean& b, int c) {
  return std::hypot(a.standardError[c], b.standardError[c]);
}

// z = |mean_a - mean_b| / (standard error of the difference), in channel c.
inline double meanZ(const ImageMean& a, const ImageMean& b, int c) {
  return std::abs(a.mean[c] - b.mean[c]) / differenceError(a, b, c);
}

// Fails the calling test unless every pair of means (of renders by different estimators,
// named by `names`) agrees: z < 4 per channel, as render_test's Cornell box, and the noise
// of the difference is below 3% of the signal, so that the comparison is sharp.
inline void expectAgreement(const std::vector<ImageMean>& means, const std::vector<std::string>& names) {
  for (size_t a = 0; a < means.size(); ++a) {
    for (size_t b = a + 1; b < means.size(); ++b) {
      for (int c = 0; c < 3; ++c) {
        EXPECT_LT(meanZ(means[a], means[b], c), 4.0)
            << names[a] << " vs " << names[b] << ", channel " << c << ": " << means[a].mean[c] << " vs "
            << means[b].mean[c] << " (se " << differenceError(means[a], means[b], c) << ")";
        EXPECT_LT(differenceError(means[a], means[b], c), 0.03 * means[0].mean[c]);
      }
    }
  }
}

}  // namespace wp::test
