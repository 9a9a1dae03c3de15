// The generated sRGB decode table (shaders/common/srgb_table.h, tools/make_srgb_table.py) that
// texture lookups read on C++ and OpenCL: each entry is the decode of its byte, and the formula
// GLSL computes instead gives the same values to float precision, so the backends agree.
#include "shaders/common/texture.h"

#include <gtest/gtest.h>

#include <cmath>

namespace wp::gpu {
namespace {

// IEC 61966-2-1, in double precision: the generator's formula, written again here.
double srgbDecode(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }

TEST(SrgbTable, EachEntryIsTheDecodeOfItsByteRoundedOnce) {
  for (uint32_t byte = 0; byte < 256; ++byte) {
    EXPECT_EQ(kSrgbToLinear[byte], float(srgbDecode(byte / 255.0))) << "byte " << byte;
    EXPECT_EQ(srgbByteToLinear(byte), kSrgbToLinear[byte]) << "byte " << byte;
  }
  EXPECT_EQ(kSrgbToLinear[0], 0.0f);
  EXPECT_EQ(kSrgbToLinear[255], 1.0f);
}

// What texture.h computes on Vulkan (srgbToLinear of the byte's value, in single precision),
// within 1e-6 of the table's values relative: the byte's value, the shift and the division
// each round once, and pow multiplies their relative error by 2.4 (the largest difference here
// is 4.4e-7, five float steps). One 8-bit step is 0.9% of a value or more, so the backends see
// the same textures.
TEST(SrgbTable, AgreesWithTheSinglePrecisionFormulaGlslComputes) {
  for (uint32_t byte = 0; byte < 256; ++byte) {
    const float glsl = srgbToLinear(float(byte) * (1.0f / 255.0f));
    EXPECT_NEAR(glsl, kSrgbToLinear[byte], 1e-6f * kSrgbToLinear[byte]) << "byte " << byte;
  }
}

}  // namespace
}  // namespace wp::gpu
