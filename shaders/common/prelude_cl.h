// OpenCL C mapping of the portable shader language.
#ifndef WP_PRELUDE_CL_H
#define WP_PRELUDE_CL_H

typedef float2 vec2;
typedef float3 vec3;
typedef float4 vec4;
typedef uint2 uvec2;
typedef uint4 uvec4;

// Whether `x` holds in every active lane of the subgroup; only steers performance.
#define WP_SUBGROUP_ALL(x) (x)
// 1 where each work-item runs as a thread of its own (a CPU device: the backend passes
// -DWP_WORK_ITEMS_ARE_THREADS=1), 0 where work-items are SIMD lanes that run both sides of a
// branch any of them takes (GPUs). Steers how the traversal spends instructions.
#ifndef WP_WORK_ITEMS_ARE_THREADS
#define WP_WORK_ITEMS_ARE_THREADS 0
#endif
#if WP_WORK_ITEMS_ARE_THREADS
// Starts fetching the cache line that holds `lvalue` (a CPU's prefetch instruction).
#define WP_PREFETCH(lvalue) __builtin_prefetch(&(lvalue))
#endif
// Sine and cosine of the angle of a sample warp (a disk or a cone of directions), where an
// error of a few units in the last place moves the sample point by as little and every
// density is taken from the point made: the native forms. PoCL's full-precision sin and cos
// reduce their argument in full on every call; its native ones made shade 11% faster on the
// Cornell box.
#define WP_WARP_SIN(angle) native_sin(angle)
#define WP_WARP_COS(angle) native_cos(angle)
// x^y in a BSDF's terms (x >= 0, y > 0; x = 0 gives 0), as exp2 of a product: its relative
// error, a few units in the last place times |y log2(x)|, is far below what a distribution or
// a fit of one needs. PoCL's pow computes in extended precision: 30% of a render of the sheen
// samples, and their shade twice as long.
#define WP_BSDF_POW(x, y) exp2((y) * log2(x))
#define WP_BEGIN
#define WP_END
#define WP_FN
// A function on a stage's hot path (the stage bodies, shade's steps, the sampler's draws,
// the traversal below the top level): PoCL's inliner keeps such functions calls, copying
// their struct arguments and results through the stack (shadeHit had a 1.5 KB frame), so
// they are inlined as if written in place. PoCL on the Lambertian Cornell box: shade 15%,
// generate 20% and extend 4% faster, images bit-identical; the first compile of the kernels
// 3.6 -> 6.1 s. Inlining every function as well (the BSDF models, textures, the top level)
// took 27 s to compile for a few percent more. Of the BSDF models, glTF's dielectric BRDF
// (evalPlastic, samplePlastic, specularLayerTransmission) and the base material's sampling
// are inlined, the most common material of glTF files: shade 8% faster on the Blender box,
// 5% on the instanced scene, no longer to compile.
#define WP_FN_INLINED __attribute__((always_inline))
// What the scene has (prelude_glsl.h), and the render's light selection: the backend builds a
// program for each scene with what it lacks defined false (openClProgramOptions); on, as here,
// where nothing says.
#ifndef WP_SCENE_ALPHA_TESTED
#define WP_SCENE_ALPHA_TESTED true
#endif
#ifndef WP_SCENE_LAYERED
#define WP_SCENE_LAYERED true
#endif
#ifndef WP_SCENE_BASE_COLOR_TEXTURE
#define WP_SCENE_BASE_COLOR_TEXTURE true
#endif
#ifndef WP_SCENE_METALLIC_ROUGHNESS_TEXTURE
#define WP_SCENE_METALLIC_ROUGHNESS_TEXTURE true
#endif
#ifndef WP_SCENE_NORMAL_TEXTURE
#define WP_SCENE_NORMAL_TEXTURE true
#endif
#ifndef WP_SCENE_EMISSIVE_TEXTURE
#define WP_SCENE_EMISSIVE_TEXTURE true
#endif
#ifndef WP_SCENE_EXTENSION_TEXTURES
#define WP_SCENE_EXTENSION_TEXTURES true
#endif
#ifndef WP_SCENE_TRANSMISSIVE
#define WP_SCENE_TRANSMISSIVE true
#endif
#ifndef WP_SCENE_MICROFACET
#define WP_SCENE_MICROFACET true
#endif
#ifndef WP_SCENE_METALLIC
#define WP_SCENE_METALLIC true
#endif
#ifndef WP_SCENE_EMISSIVE
#define WP_SCENE_EMISSIVE true
#endif
#ifndef WP_SCENE_SKY_SAMPLED
#define WP_SCENE_SKY_SAMPLED true
#endif
#ifndef WP_SCENE_INSTANCED
#define WP_SCENE_INSTANCED true
#endif
#ifndef WP_SCENE_PLANES
#define WP_SCENE_PLANES true
#endif
#ifndef WP_SCENE_SPHERES
#define WP_SCENE_SPHERES true
#endif
#ifndef WP_SCENE_SKY_MAP
#define WP_SCENE_SKY_MAP true
#endif
#ifndef WP_SCENE_PUNCTUAL
#define WP_SCENE_PUNCTUAL true
#endif
#ifndef WP_RENDER_SOLID_ANGLE_SELECTION
#define WP_RENDER_SOLID_ANGLE_SELECTION true
#endif
// OpenCL tests RenderParams.featurePasses and samplerKind as it runs: PoCL's branches are real.
#define WP_RENDER_FEATURE_PASSES true
#define WP_RENDER_INDEPENDENT_SAMPLER true
#define WP_STRUCT(name) typedef struct name {
#define WP_STRUCT_END(name) } name;
// A file-scope table of float constants: WP_FLOAT_TABLE(name, size) v0, v1, ... WP_FLOAT_TABLE_END
#define WP_FLOAT_TABLE(name, size) __constant float name[size] = {
#define WP_FLOAT_TABLE_END };
#define WP_GLOBAL_PTR(type) __global const type*
#define WP_GLOBAL_MUTABLE_PTR(type) __global type*

#define make_vec2(x, y) ((float2)((x), (y)))
#define make_vec3(x, y, z) ((float3)((x), (y), (z)))
#define make_vec4(x, y, z, w) ((float4)((x), (y), (z), (w)))
#define make_uvec4(x, y, z, w) ((uint4)((x), (y), (z), (w)))
#define toFloat(x) ((float)(x))
#define toFloat4(x) convert_float4(x)
#define notANumber(x) isnan(x)
#define toUint(x) ((uint)(x))
#define toInt(x) ((int)(x))
#define asFloat(x) as_float(x)
#define asUint(x) as_uint(x)
// Atomic add on a buffer element, returning the value before.
#define WP_ATOMIC_ADD(element, n) atomic_add(&(element), n)
// Adds a vec3 to the xyz of a vec4 (for a buffer element, a write of three components).
#define WP_ADD_XYZ(element, v) (element).xyz += (v)
// Sets the xyz of a vec4 and keeps its w (for a buffer element, a write of three components).
#define WP_SET_XYZ(element, v) (element).xyz = (v)
// The xyz of a vec4 (for a buffer element, a read of three components).
#define WP_XYZ(v) (v).xyz

#endif
