// Textures sampled by hand from the texel buffer (RGBA8 packed in uints), so both backends
// share one implementation: each slot's texture coordinate set and KHR_texture_transform,
// wrap modes per axis, nearest or bilinear filtering, sRGB decode.
#ifndef WP_TEXTURE_H
#define WP_TEXTURE_H

#include "binding_table.h"
#include "surface.h"
#ifdef WP_BUFFERS_AS_ARGUMENTS
#include "srgb_table.h"
#endif

WP_BEGIN


// i mod size for any integer i, without the sign of % on negative numbers (undefined in GLSL).
WP_FN int floorMod(int i, int size) { return i - size * toInt(floor(toFloat(i) / toFloat(size))); }

// The texel index along one axis for texel coordinate i under a glTF wrap mode.
WP_FN int wrapTexel(int i, int size, uint mode) {
  if (mode == WP_TEXTURE_WRAP_CLAMP) {
    return max(0, min(i, size - 1));
  }
  if (mode == WP_TEXTURE_WRAP_MIRROR) {
    int m = floorMod(i, 2 * size);
    return m < size ? m : 2 * size - 1 - m;
  }
  return floorMod(i, size);
}

// The sRGB decode (IEC 61966-2-1) of c in [0, 1], in single precision.
WP_FN float srgbToLinear(float c) {
  return c <= 0.04045f ? c * (1.0f / 12.92f) : pow((c + 0.055f) * (1.0f / 1.055f), 2.4f);
}

// The sRGB decode of the 8-bit value `byte`. C++ and OpenCL read the exact decode from the
// generated table: PoCL's full-precision pow took 43% of a render of a Blender scene with one
// base colour texture (a bilinear lookup decodes twelve channels). GPUs, and lavapipe, compute
// pow in a few instructions, where a table would be a memory access a lane.
#ifdef WP_BUFFERS_AS_ARGUMENTS
WP_FN float srgbByteToLinear(uint byte) { return kSrgbToLinear[byte]; }
#else
WP_FN float srgbByteToLinear(uint byte) { return srgbToLinear(toFloat(byte) * (1.0f / 255.0f)); }
#endif

// Texel (x, y), already wrapped, as linear RGBA in [0, 1].
WP_FN vec4 texelAt(WP_BUFFERS GpuTexture t, int x, int y) {
  uint packed = WP_LOAD(texels, textureFirstTexel(t) + toUint(y) * textureWidth(t) + toUint(x));
  if (textureIsSrgb(t)) {
    return make_vec4(srgbByteToLinear(packed & 255u), srgbByteToLinear((packed >> 8u) & 255u),
                     srgbByteToLinear((packed >> 16u) & 255u), toFloat(packed >> 24u) * (1.0f / 255.0f));
  }
  return unpackUnorm8(packed);
}

// Texture t at uv (glTF: origin at the image's top-left, v down), uv already transformed.
// Bilinear filtering blends in linear space (after the sRGB decode), as GPUs do with sRGB
// formats.
WP_FN vec4 filterTexture(WP_BUFFERS GpuTexture t, vec2 uv) {
  int width = toInt(textureWidth(t));
  int height = toInt(textureHeight(t));
  uint wrapS = textureWrapS(t);
  uint wrapT = textureWrapT(t);
  float x = uv.x * toFloat(width);
  float y = uv.y * toFloat(height);
  if (textureIsNearest(t)) {
    return texelAt(WP_BUFFERS_ARG t, wrapTexel(toInt(floor(x)), width, wrapS),
                   wrapTexel(toInt(floor(y)), height, wrapT));
  }
  // Texel centres sit at half-integer coordinates.
  float fx = floor(x - 0.5f);
  float fy = floor(y - 0.5f);
  float ax = x - 0.5f - fx;
  float ay = y - 0.5f - fy;
  int x0 = wrapTexel(toInt(fx), width, wrapS);
  int x1 = wrapTexel(toInt(fx) + 1, width, wrapS);
  int y0 = wrapTexel(toInt(fy), height, wrapT);
  int y1 = wrapTexel(toInt(fy) + 1, height, wrapT);
  vec4 top = texelAt(WP_BUFFERS_ARG t, x0, y0) * (1.0f - ax) + texelAt(WP_BUFFERS_ARG t, x1, y0) * ax;
  vec4 bottom = texelAt(WP_BUFFERS_ARG t, x0, y1) * (1.0f - ax) + texelAt(WP_BUFFERS_ARG t, x1, y1) * ax;
  return top * (1.0f - ay) + bottom * ay;
}

// The coordinates texture t looks up at c: its slot's set (glTF texCoord, or the
// KHR_texture_transform's own) through the slot's transform.
WP_FN vec2 textureUv(GpuTexture t, TexCoords c) {
  vec2 uv = textureUsesTexCoord1(t) ? c.set1 : c.set0;
  vec3 p = make_vec3(uv.x, uv.y, 1.0f);
  return make_vec2(dot(textureUvTransformU(t), p), dot(textureUvTransformV(t), p));
}

// Whether texture `index` (WP_INVALID: none) applies at c: it exists and the surface has its
// coordinate set (without it the slot's factor stands alone).
WP_FN bool textureApplies(WP_BUFFERS uint index, TexCoords c) {
  if (index == WP_INVALID) {  // (a constant where the scene lacks the slot: layout.h)
    return false;
  }
  return textureUsesTexCoord1(WP_LOAD(textures, index)) ? c.hasSet1 : c.hasSet0;
}

// Texture `index` at c, where textureApplies.
WP_FN vec4 sampleTexture(WP_BUFFERS uint index, TexCoords c) {
  GpuTexture t = WP_LOAD(textures, index);
  return filterTexture(WP_BUFFERS_ARG t, textureUv(t, c));
}

// Emitted radiance `factor` (glTF: emissiveFactor times KHR_materials_emissive_strength)
// times the emissive texture `index` at c; the factor alone without a texture (WP_INVALID)
// or without its texture coordinates. Hits and light samples both take it from here, so they
// agree.
WP_FN vec3 texturedEmission(WP_BUFFERS vec3 factor, uint index, TexCoords c) {
  if (!textureApplies(WP_BUFFERS_ARG index, c)) {
    return factor;
  }
  vec4 t = sampleTexture(WP_BUFFERS_ARG index, c);
  return factor * make_vec3(t.x, t.y, t.z);
}

WP_END

#endif
