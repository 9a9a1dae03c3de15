// Image means with their standard errors, and the z statistic that compares two of them.
#pragma once

#include <cmath>

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

}  // namespace wp::test
