// Device buffers of both backends: what they copy in, and how they meet the device's limits.
#include <gtest/gtest.h>

#include <array>

#include "backend/opencl/cl_check.h"
#include "backend/opencl/opencl_buffer.h"
#include "backend/opencl/opencl_context.h"

namespace wp::test {
namespace {

TEST(OpenClBuffer, ASourceSmallerThanThePlaceholderIsCopiedAndPaddedWithZeros) {
  // The sky's row distribution of a one-texel sky is 8 bytes; the buffer is 16, and it used
  // to copy 16 bytes from the 8-byte source. Here the 8 bytes are followed by 7s, which a copy
  // past the source would bring along (under ASan a heap source is reported at once).
  OpenClContext context(-1);
  const std::array<float, 4> region = {0.25f, 0.5f, 7.0f, 7.0f};
  OpenClBuffer buffer(context.context, CL_MEM_READ_ONLY, 2 * sizeof(float), region.data());
  ASSERT_EQ(buffer.size(), 16u);
  std::array<float, 4> back{};
  CL_CHECK(clEnqueueReadBuffer(context.queue, buffer.handle(), CL_TRUE, 0, sizeof(back), back.data(), 0, nullptr,
                               nullptr));
  EXPECT_EQ(back, (std::array<float, 4>{0.25f, 0.5f, 0.0f, 0.0f}));
}

}  // namespace
}  // namespace wp::test
