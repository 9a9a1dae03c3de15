// GLSL mapping of the portable shader language.
#ifndef WP_PRELUDE_GLSL_H
#define WP_PRELUDE_GLSL_H

// Whether `x` holds in every active lane of the subgroup; only steers performance.
#ifdef GL_KHR_shader_subgroup_vote
#define WP_SUBGROUP_ALL(x) subgroupAll(x)
#else
#define WP_SUBGROUP_ALL(x) (x)
#endif
// Work-items are SIMD lanes (lavapipe's, and a GPU's), never threads of their own.
#define WP_WORK_ITEMS_ARE_THREADS 0
// The traversal's stacks may live in workgroup memory (traverse.h).
#define WP_GLSL 1
// Sine and cosine of a sample warp's angle (prelude_cl.h): GLSL's own precision suffices.
#define WP_WARP_SIN(angle) sin(angle)
#define WP_WARP_COS(angle) cos(angle)
// x^y in a BSDF's terms (prelude_cl.h): GLSL's pow is exp2 of a product already.
#define WP_BSDF_POW(x, y) pow((x), (y))
#define WP_BEGIN
#define WP_END
#define WP_FN
#define WP_FN_INLINED  // Mesa inlines every function
#define WP_STRUCT(name) struct name {
#define WP_STRUCT_END(name) };

#define make_vec2(x, y) vec2((x), (y))
#define make_vec3(x, y, z) vec3((x), (y), (z))
#define make_vec4(x, y, z, w) vec4((x), (y), (z), (w))
#define make_uvec4(x, y, z, w) uvec4((x), (y), (z), (w))
#define toFloat(x) float(x)
#define toFloat4(x) vec4(x)
#define notANumber(x) isnan(x)
#define toUint(x) uint(x)
#define toInt(x) int(x)
#define asFloat(x) uintBitsToFloat(x)
#define asUint(x) floatBitsToUint(x)
// Atomic add on a buffer element, returning the value before.
#define WP_ATOMIC_ADD(element, n) atomicAdd(element, n)
// Adds a vec3 to the xyz of a vec4 (for a buffer element, a write of three components).
#define WP_ADD_XYZ(element, v) (element).xyz += (v)
// Sets the xyz of a vec4 and keeps its w (for a buffer element, a write of three components).
#define WP_SET_XYZ(element, v) (element).xyz = (v)
// The xyz of a vec4 (for a buffer element, a read of three components).
#define WP_XYZ(v) (v).xyz

// What the scene uses (GpuScene::features): specialization constants the Vulkan backend
// sets per scene, so that the code of a feature the scene lacks compiles away (lavapipe pays
// for it even where it never runs). C++ and OpenCL keep them all true.
layout(constant_id = 0) const bool WP_SCENE_ALPHA_TESTED = true;  // traverse.h
layout(constant_id = 1) const bool WP_SCENE_LAYERED = true;       // material.h
layout(constant_id = 2) const bool WP_SCENE_BASE_COLOR_TEXTURE = true;  // layout.h
layout(constant_id = 3) const bool WP_SCENE_TRANSMISSIVE = true;  // material.h
layout(constant_id = 4) const bool WP_SCENE_MICROFACET = true;    // bsdf.h
layout(constant_id = 5) const bool WP_SCENE_METALLIC = true;      // material.h
layout(constant_id = 6) const bool WP_SCENE_EMISSIVE = true;      // integrator.h, lights.h
layout(constant_id = 7) const bool WP_SCENE_SKY_SAMPLED = true;   // integrator.h
// And what the render uses (RenderParams): its light selection by solid angle (lights.h).
layout(constant_id = 8) const bool WP_RENDER_SOLID_ANGLE_SELECTION = true;
// (9 and 10 are shade.comp's.) Where the traversal keeps its stacks (traverse.h): in workgroup
// memory, each level's of the entries the scene's trees need (GpuScene::stackNeeds), or in
// each invocation's own arrays, the size any tree may need.
layout(constant_id = 11) const bool WP_STACKS_IN_WORKGROUP_MEMORY = false;
layout(constant_id = 12) const uint WP_TOP_LEVEL_STACK_ENTRIES = 1u;
layout(constant_id = 13) const uint WP_BOTTOM_LEVEL_STACK_ENTRIES = 1u;
// Whether the top level's root is a node (GpuScene::topLevelEntry, traverse.h): false where it
// is a single instance's leaf, which the traversal then enters without the walk's code.
layout(constant_id = 14) const bool WP_SCENE_INSTANCED = true;
// Whether the scene has planes (traverse.h, surface.h): their loop runs once per ray on
// lavapipe even where there are none.
layout(constant_id = 15) const bool WP_SCENE_PLANES = true;
// Whether the scene has spheres (traverse.h, surface.h), and whether its sky is a map of more
// than one texel (environment.h): lavapipe runs both sides of every branch, so a triangle
// hit paid for the sphere's and the plane's surface, and a miss under a uniform sky for the
// map's two arctangents.
layout(constant_id = 16) const bool WP_SCENE_SPHERES = true;
layout(constant_id = 17) const bool WP_SCENE_SKY_MAP = true;
// Whether the scene has punctual lights (KHR_lights_punctual, lights.h): a light sample ran
// their sampling beside the emissive triangle's in a scene lit by triangles alone.
layout(constant_id = 18) const bool WP_SCENE_PUNCTUAL = true;
// Whether the render keeps feature passes (RenderParams.featurePasses, integrator.h,
// stages.h): their albedo, normal and depth were written for every hit and summed for every
// pixel of a PNG too.
layout(constant_id = 19) const bool WP_RENDER_FEATURE_PASSES = true;
// Whether the render draws from the independent sampler (RenderParams.samplerKind, sampler.h):
// false compiles it out of a Sobol render's stages.
layout(constant_id = 20) const bool WP_RENDER_INDEPENDENT_SAMPLER = true;
// Which of the materials' texture slots the scene fills (layout.h; the base colour's is
// constant 2): lavapipe ran the lookups of all eleven slots for every hit, where a scene made
// in Blender fills two (the base colour and the normal map).
layout(constant_id = 21) const bool WP_SCENE_METALLIC_ROUGHNESS_TEXTURE = true;
layout(constant_id = 22) const bool WP_SCENE_NORMAL_TEXTURE = true;
layout(constant_id = 23) const bool WP_SCENE_EMISSIVE_TEXTURE = true;
// KHR_materials_specular's, _sheen's and _clearcoat's textures.
layout(constant_id = 24) const bool WP_SCENE_EXTENSION_TEXTURES = true;

float fabs(float x) { return abs(x); }
vec3 fabs(vec3 v) { return abs(v); }

#endif
