// C++ (GLM) mapping of the portable shader language, used by unit tests and host code.
#ifndef WP_PRELUDE_CPP_H
#define WP_PRELUDE_CPP_H

#include <algorithm>
#include <atomic>
#include <bit>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>

namespace wp::gpu {
using namespace glm;
using uint = std::uint32_t;

inline float fabs(float x) { return std::fabs(x); }
inline vec3 fabs(vec3 v) { return glm::abs(v); }
inline float asFloat(uint u) { return std::bit_cast<float>(u); }
inline uint asUint(float f) { return std::bit_cast<uint>(f); }
// The most entries each level's traversal stack has held on this thread (traverse.h), which
// the tests compare with what traversalStackEntries says the trees need.
struct DeepestStacks {
  uint topLevelStack = 0;
  uint bottomLevelStack = 0;
};
inline thread_local DeepestStacks deepestStacks;
}  // namespace wp::gpu
#define WP_NOTE_STACK_ENTRY(stack, i) (deepestStacks.stack = std::max(deepestStacks.stack, (i) + 1u))

// The host reference places moving instances at every time (motion.h, instanceAt).
#define WP_MOTION_BLUR 1
// Whether `x` holds in every active lane of the subgroup; only steers performance.
#define WP_SUBGROUP_ALL(x) (x)
#define WP_WORK_ITEMS_ARE_THREADS 1
#define WP_PREFETCH(lvalue) __builtin_prefetch(&(lvalue))
// Sine and cosine of a sample warp's angle (prelude_cl.h): the host's are the reference.
#define WP_WARP_SIN(angle) std::sin(angle)
#define WP_WARP_COS(angle) std::cos(angle)
// x^y in a BSDF's terms (prelude_cl.h): the host's pow is the reference.
#define WP_BSDF_POW(x, y) std::pow((x), (y))
#define WP_BEGIN namespace wp::gpu {
#define WP_END }
#define WP_FN inline
#define WP_FN_INLINED inline
// What the scene has (prelude_glsl.h): Vulkan and OpenCL specialize the stages to it; C++ runs
// everything.
#define WP_SCENE_ALPHA_TESTED true
#define WP_SCENE_LAYERED true
#define WP_SCENE_BASE_COLOR_TEXTURE true
#define WP_SCENE_METALLIC_ROUGHNESS_TEXTURE true
#define WP_SCENE_NORMAL_TEXTURE true
#define WP_SCENE_EMISSIVE_TEXTURE true
#define WP_SCENE_EXTENSION_TEXTURES true
#define WP_SCENE_TRANSMISSIVE true
#define WP_SCENE_MICROFACET true
#define WP_SCENE_METALLIC true
#define WP_SCENE_EMISSIVE true
#define WP_SCENE_SKY_SAMPLED true
#define WP_SCENE_INSTANCED true
#define WP_SCENE_PLANES true
#define WP_SCENE_SPHERES true
#define WP_SCENE_SKY_MAP true
#define WP_SCENE_PUNCTUAL true
#define WP_RENDER_SOLID_ANGLE_SELECTION true
#define WP_RENDER_FEATURE_PASSES true
#define WP_RENDER_INDEPENDENT_SAMPLER true
#define WP_STRUCT(name) struct name {
#define WP_STRUCT_END(name) };
// A file-scope table of float constants: WP_FLOAT_TABLE(name, size) v0, v1, ... WP_FLOAT_TABLE_END
#define WP_FLOAT_TABLE(name, size) inline constexpr float name[size] = {
#define WP_FLOAT_TABLE_END };
// Pointer to device-global memory in function parameters (GLSL reads buffers as globals).
#define WP_GLOBAL_PTR(type) const type*
#define WP_GLOBAL_MUTABLE_PTR(type) type*

#define make_vec2(x, y) vec2((x), (y))
#define make_vec3(x, y, z) vec3((x), (y), (z))
#define make_vec4(x, y, z, w) vec4((x), (y), (z), (w))
#define make_uvec4(x, y, z, w) uvec4((x), (y), (z), (w))
#define toFloat(x) static_cast<float>(x)
#define toFloat4(x) vec4(x)
inline bool notANumber(float x) { return std::isnan(x); }
#define toUint(x) static_cast<uint>(x)
#define toInt(x) static_cast<int>(x)
// Atomic add on a buffer element, returning the value before.
#define WP_ATOMIC_ADD(element, n) std::atomic_ref<uint>(element).fetch_add(n)
// Adds a vec3 to the xyz of a vec4.
#define WP_ADD_XYZ(element, v) (element) += vec4((v), 0.0f)
// Sets the xyz of a vec4 and keeps its w (for a buffer element, a write of three components).
#define WP_SET_XYZ(element, v) (element) = vec4((v), (element).w)
// The xyz of a vec4.
#define WP_XYZ(v) vec3(v)

#endif
