// `wavepath merge`: parts of one frame (batches of its samples, regions of it, or both)
// combined into the frame.
#pragma once

#include <string>
#include <vector>

#include "image/image_io.h"

namespace wp {

// One part as read from its EXR, with the name to use in messages.
struct FramePart {
  std::string name;
  RadianceImage image;  // with its record and variance
};

// The frame the parts make. Every part must carry a render record (an EXR written by
// `wavepath render`) of the same frame (size, spp, seed, settings and scene hash), no two
// parts may hold the same sample of the same pixel, and together they must hold every
// sample of every pixel; otherwise throws a one-line wp::Error naming the parts.
//
// Per pixel, the parts holding it are combined in sample order: the mean is
// sum_k n_k m_k / N (in double, n_k the part's samples of the pixel: its sample range, or its
// samples.X where adaptive sampling stopped the pixel early; m_k its mean), and the variance of
// that mean comes from the parts' sample variances s_k^2 = n_k v_k by Chan et al.'s
// pairwise formula, M2 = sum_k (n_k - 1) s_k^2 + sum_k n_k (m_k - mean)^2, v = M2 / (N (N - 1)).
// A pixel held by one part (regions) keeps its values bit for bit.
RadianceImage mergeParts(const std::vector<FramePart>& parts);

}  // namespace wp
