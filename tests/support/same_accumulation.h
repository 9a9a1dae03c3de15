// Whether two renders' accumulations are the same bit for bit: for tests of changes that must
// leave the images as they were (a stage split, specialized or reordered; work left out).
#pragma once

#include <gtest/gtest.h>

#include <cstdint>

#include "render/backend.h"

namespace wp::test {

// Every layer of `a` and `b` the same, bit for bit, and `a` not black.
inline void expectSameBitForBit(const Accumulation& a, const Accumulation& b) {
  double total = 0.0;
  for (const glm::vec4& s : a.sum) total += s.x + s.y + s.z;
  EXPECT_GT(total, 0.0) << "the render is black";
  for (uint32_t layer = 0; layer < WP_ACCUMULATION_LAYERS; ++layer) {
    EXPECT_TRUE(*a.layers()[layer] == *b.layers()[layer]) << "layer " << layer << " differs";
  }
}

}  // namespace wp::test
