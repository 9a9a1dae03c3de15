// What every Vulkan stage declares (one descriptor set): each buffer of the binding table
// (common/binding_table.h) and, for a texel buffer, its <name>At(i) loader, which
// WP_LOAD(name, i) calls; the push constants.
#include "common/binding_table.h"

layout(local_size_x = WP_WORKGROUP_SIZE) in;

// The dispatch's PassConstants, then the render parameters' entry in their uniform buffer
// (always 0; WP_GLSL_UNIFORM below says why it is not a constant).
layout(push_constant) uniform Push {
  PassConstants pc;
  uint paramsEntry;
};

#define WP_GLSL_BINDING(name, binding, Element, stride, format, access, backends) \
  WP_GLSL_##access(name, binding, Element, stride, format)
// The render parameters: a uniform buffer read at an entry given by a push constant. Read at
// a constant offset, lavapipe (Mesa 22.3) inlines uniform values that a branch or loop tests
// (the lights, planes and aperture blades counted in RenderParams, the mode) into the shader
// and compiles it anew at every bind, never freeing the copies: a 10,000-spp render grew by
// 100 MB (wavepath-bench-soak, docs/robustness.md; LongRender.PassesCompileNoShaders). Read
// from a storage buffer, each parameter was loaded lane by lane, a third of shade's time; an
// offset computed from push constants is one load for all lanes and inlines nothing.
#define WP_GLSL_UNIFORM(name, index, Element, stride, format) \
  layout(std140, binding = index) uniform name##Block { Element name##Entries[1]; };
#define WP_GLSL_STORAGE(name, index, Element, stride, format)              \
  layout(std430, binding = index) buffer name##Block { Element name[]; }; \
  WP_GLSL_STORAGE_LOADER_##format(name, Element)
// A storage buffer's loader reads the buffer itself, or for VIEWED its texel view (a later row
// declares it): on lavapipe a storage-buffer load is a loop over the lanes for each
// component, a texel fetch one gather of the whole texel.
#define WP_GLSL_STORAGE_LOADER_NONE(name, Element) \
  Element name##At(uint i) { return name[i]; }
#define WP_GLSL_STORAGE_LOADER_VIEWED(name, Element)
#define WP_GLSL_WRITE(name, index, Element, stride, format) \
  layout(std430, binding = index) writeonly buffer name##Block { Element name[]; };
#define WP_GLSL_TEXELS(name, index, Element, stride, format) \
  layout(binding = index) uniform usamplerBuffer name##Texels; WP_GLSL_LOADER_##format(name, Element, stride)
#define WP_GLSL_TEXEL_VIEW(name, index, Element, stride, format) WP_GLSL_TEXELS(name, index, Element, stride, format)
#define WP_GLSL_CONSTANT(name, index, Element, stride, format) WP_GLSL_TEXELS(name, index, Element, stride, format)

// A record of `stride` texels reads one field per texel, in the order WP_FIELDS_<Element>
// lists them; the texel buffer is a parameter because the field macro cannot name it.
#define WP_GLSL_LOADER_RECORD(name, Element, stride)                                      \
  Element load##Element(usamplerBuffer texels, uint t) {                                  \
    Element e;                                                                            \
    WP_FIELDS_##Element(WP_GLSL_LOAD_FIELD) return e;                                     \
  }                                                                                       \
  Element name##At(uint i) { return load##Element(name##Texels, i * uint(stride)); }
#define WP_GLSL_LOAD_FIELD(type, field) e.field = WP_GLSL_FROM_TEXEL_##type(texelFetch(texels, int(t))); ++t;
#define WP_GLSL_FROM_TEXEL_vec4(texel) uintBitsToFloat(texel)
#define WP_GLSL_FROM_TEXEL_uvec4(texel) (texel)
#define WP_GLSL_LOADER_VEC4(name, Element, stride) \
  vec4 name##At(uint i) { return uintBitsToFloat(texelFetch(name##Texels, int(i))); }
#define WP_GLSL_LOADER_R32(name, Element, stride) \
  float name##At(uint i) { return uintBitsToFloat(texelFetch(name##Texels, int(i)).x); }
#define WP_GLSL_LOADER_WORDS(name, Element, stride) \
  uint name##At(uint i) { return texelFetch(name##Texels, int(i >> 2u))[i & 3u]; }

WP_BINDINGS(WP_GLSL_BINDING)

// The render parameters, as the stages take them (from the uniform block above).
RenderParams renderParams() { return paramsEntries[paramsEntry]; }

