// GPU buffer structs and workgroup sizes shared by host, GLSL and OpenCL. Every struct is
// made of 16-byte vec4/uvec4 fields, or of 4-byte scalars in groups of four, so std140,
// std430, OpenCL and C++ agree on the layout; the host checks sizes and offsets with
// static_assert (src/render/gpu_layout_check.cpp). A struct that a stage reads from a buffer
// is a record: its fields are listed once, F(type, name) in WP_FIELDS_<Name>, from which
// WP_RECORD declares it and the Vulkan stages generate its texel loader (binding_table.h
// says which buffer holds which record). Records pack several values into a vec4; code
// reads them through the named accessors that follow each record (rayBounce(ray), never
// ray.state.y), the same names in GLSL, OpenCL C and C++.
#ifndef WP_LAYOUT_H
#define WP_LAYOUT_H

#include "portable.h"
#include "sampler.h"
#include "thin_lens.h"

WP_BEGIN

#define WP_WORKGROUP_SIZE 64

// Integrator modes (RenderParams.mode).
#define WP_MODE_MIS 0u
#define WP_MODE_NEE 1u
#define WP_MODE_BSDF 2u

// Light selection for next event estimation (RenderParams.lightSelection).
#define WP_LIGHT_SELECTION_POWER 0u        // alias table by emitted power
#define WP_LIGHT_SELECTION_SOLID_ANGLE 1u  // by subtended solid angle times luminance (lights.h)

// What an instance is (instanceKind).
#define WP_INSTANCE_MESH 0u
#define WP_INSTANCE_SPHERE 1u  // unit sphere at the object-space origin

#define WP_INVALID 0xffffffffu

// A traversal stack entry (traverse.h), also the top level's root in RenderParams: a node
// (count 0) or a leaf of `count` primitives at `index`, the count in the bits above the index.
#define WP_ENTRY_COUNT_SHIFT 29u
#define WP_ENTRY_INDEX_MASK 0x1fffffffu
WP_FN uint packEntry(uint index, uint count) { return index | (count << WP_ENTRY_COUNT_SHIFT); }
WP_FN uint entryIndex(uint entry) { return entry & WP_ENTRY_INDEX_MASK; }
WP_FN uint entryCount(uint entry) { return entry >> WP_ENTRY_COUNT_SHIFT; }

// 4-wide BVH node, 128 bytes: the bounds of up to four children, one vec4 per axis bound with
// a child in each component (x: child 0 ... w: child 3), so one vec4 operation tests an axis
// for all four children (SIMD on CPUs, where PoCL runs a work-item as scalar code), then the
// children's indices and leaf counts. A child with count 0 is an interior node at `index`; a
// child with count > 0 is a leaf holding primitives [index, index + count); an empty slot has
// index WP_INVALID and count 0 (its bounds are never read). Bottom-level leaves hold
// triangles, top-level leaves instances.
#define WP_FIELDS_BvhNode(F) \
  F(vec4, childMinX)         \
  F(vec4, childMaxX)         \
  F(vec4, childMinY)         \
  F(vec4, childMaxY)         \
  F(vec4, childMinZ)         \
  F(vec4, childMaxZ)         \
  F(uvec4, childIndex)       \
  F(uvec4, childCount)
WP_RECORD(BvhNode)
#define WP_BVH_WIDTH 4u

// Triangle in object space, stored in BVH leaf order: 64 bytes.
//   v0: xyz: vertex 0; w: 1 if its material's alphaMode is MASK or BLEND (the traversal then
//     tests its coverage, alpha.h), 0 if opaque
//   edge1: xyz: v1 - v0
//   edge2: xyz: v2 - v0
//   info: x: material index, y: emitter ordinal within its mesh or WP_INVALID
#define WP_FIELDS_GpuTriangle(F) \
  F(vec4, v0)                    \
  F(vec4, edge1)                 \
  F(vec4, edge2)                 \
  F(uvec4, info)
WP_RECORD(GpuTriangle)
WP_FN vec3 triangleVertex0(GpuTriangle t) { return make_vec3(t.v0.x, t.v0.y, t.v0.z); }
// Kept in v0.w, which the traversal loads anyway, so opaque triangles cost no extra fetch.
WP_FN bool triangleAlphaTested(GpuTriangle t) { return t.v0.w != 0.0f; }
WP_FN vec3 triangleEdge1(GpuTriangle t) { return make_vec3(t.edge1.x, t.edge1.y, t.edge1.z); }
WP_FN vec3 triangleEdge2(GpuTriangle t) { return make_vec3(t.edge2.x, t.edge2.y, t.edge2.z); }
WP_FN uint triangleMaterial(GpuTriangle t) { return t.info.x; }
// Its ordinal among its mesh's emitters (its light is the instance's first light plus it),
// or WP_INVALID.
WP_FN uint triangleEmitter(GpuTriangle t) { return t.info.y; }
WP_FN GpuTriangle makeGpuTriangle(vec3 v0, vec3 v1, vec3 v2, uint material, uint emitter) {
  vec3 edge1 = v1 - v0;
  vec3 edge2 = v2 - v0;
  GpuTriangle t;
  t.v0 = make_vec4(v0.x, v0.y, v0.z, 0.0f);
  t.edge1 = make_vec4(edge1.x, edge1.y, edge1.z, 0.0f);
  t.edge2 = make_vec4(edge2.x, edge2.y, edge2.z, 0.0f);
  t.info = make_uvec4(material, emitter, 0u, 0u);
  return t;
}
// Marks it alpha-tested (its material is MASK or BLEND), or not.
WP_FN GpuTriangle withTriangleAlphaTested(GpuTriangle t, bool alphaTested) {
  t.v0.w = alphaTested ? 1.0f : 0.0f;
  return t;
}

// Shading data of the GpuTriangle at the same index, read only when shading a hit (and by
// light samples, for the emissive texture, and the alpha test), so the traversal's triangle
// records stay 64 bytes: 160 bytes.
//   normal0..2: xyz: object-space unit vertex normals (glTF NORMAL), all three zero: shade
//     with the geometric normal (flat); w: TEXCOORD_0's u at the three vertices
//   v: xyz: TEXCOORD_0's v at the three vertices, w: 1 if the mesh has TEXCOORD_0
//   colors: xyz: COLOR_0 at the three vertices as RGBA8 (linear, r in the low byte); white
//     without COLOR_0
//   tangent0..2: xyz: object-space unit glTF TANGENTs, w: bitangent sign (+-1); all zero
//     without TANGENT (the frame then comes from the uv gradient)
//   texCoord1Vertices01: TEXCOORD_1 at vertices 0 (xy) and 1 (zw)
//   texCoord1Vertex2: xy: TEXCOORD_1 at vertex 2, z: 1 if the mesh has TEXCOORD_1, w: unused
#define WP_FIELDS_GpuTriangleShading(F) \
  F(vec4, normal0)                      \
  F(vec4, normal1)                      \
  F(vec4, normal2)                      \
  F(vec4, v)                            \
  F(uvec4, colors)                      \
  F(vec4, tangent0)                     \
  F(vec4, tangent1)                     \
  F(vec4, tangent2)                     \
  F(vec4, texCoord1Vertices01)          \
  F(vec4, texCoord1Vertex2)
WP_RECORD(GpuTriangleShading)
WP_FN vec3 vertexNormal0(GpuTriangleShading s) { return make_vec3(s.normal0.x, s.normal0.y, s.normal0.z); }
WP_FN vec3 vertexNormal1(GpuTriangleShading s) { return make_vec3(s.normal1.x, s.normal1.y, s.normal1.z); }
WP_FN vec3 vertexNormal2(GpuTriangleShading s) { return make_vec3(s.normal2.x, s.normal2.y, s.normal2.z); }
WP_FN vec2 vertexUv0(GpuTriangleShading s) { return make_vec2(s.normal0.w, s.v.x); }
WP_FN vec2 vertexUv1(GpuTriangleShading s) { return make_vec2(s.normal1.w, s.v.y); }
WP_FN vec2 vertexUv2(GpuTriangleShading s) { return make_vec2(s.normal2.w, s.v.z); }
WP_FN bool hasUv(GpuTriangleShading s) { return s.v.w != 0.0f; }
WP_FN vec2 vertexTexCoord1At0(GpuTriangleShading s) { return make_vec2(s.texCoord1Vertices01.x, s.texCoord1Vertices01.y); }
WP_FN vec2 vertexTexCoord1At1(GpuTriangleShading s) { return make_vec2(s.texCoord1Vertices01.z, s.texCoord1Vertices01.w); }
WP_FN vec2 vertexTexCoord1At2(GpuTriangleShading s) { return make_vec2(s.texCoord1Vertex2.x, s.texCoord1Vertex2.y); }
WP_FN bool hasTexCoord1(GpuTriangleShading s) { return s.texCoord1Vertex2.z != 0.0f; }
// COLOR_0 as RGBA8 (r in the low byte).
WP_FN uint vertexColor0(GpuTriangleShading s) { return s.colors.x; }
WP_FN uint vertexColor1(GpuTriangleShading s) { return s.colors.y; }
WP_FN uint vertexColor2(GpuTriangleShading s) { return s.colors.z; }
// xyz: the tangent, w: the bitangent's sign.
WP_FN vec4 vertexTangent0(GpuTriangleShading s) { return s.tangent0; }
WP_FN vec4 vertexTangent1(GpuTriangleShading s) { return s.tangent1; }
WP_FN vec4 vertexTangent2(GpuTriangleShading s) { return s.tangent2; }
// From the three vertices' values: unit normals (all zero: flat), TEXCOORD_0 (if hasUv),
// COLOR_0 as RGBA8 and tangents (xyz, w: the bitangent's sign; all zero: none).
WP_FN GpuTriangleShading makeGpuTriangleShading(vec3 normal0, vec3 normal1, vec3 normal2, vec2 uv0, vec2 uv1,
                                                vec2 uv2, bool hasUv, uint color0, uint color1, uint color2,
                                                vec4 tangent0, vec4 tangent1, vec4 tangent2) {
  GpuTriangleShading s;
  s.texCoord1Vertices01 = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
  s.texCoord1Vertex2 = make_vec4(0.0f, 0.0f, 0.0f, 0.0f);
  s.normal0 = make_vec4(normal0.x, normal0.y, normal0.z, uv0.x);
  s.normal1 = make_vec4(normal1.x, normal1.y, normal1.z, uv1.x);
  s.normal2 = make_vec4(normal2.x, normal2.y, normal2.z, uv2.x);
  s.v = make_vec4(uv0.y, uv1.y, uv2.y, hasUv ? 1.0f : 0.0f);
  s.colors = make_uvec4(color0, color1, color2, 0u);
  s.tangent0 = tangent0;
  s.tangent1 = tangent1;
  s.tangent2 = tangent2;
  return s;
}
// The triangle's TEXCOORD_1 at its three vertices (a mesh without the set keeps none).
WP_FN GpuTriangleShading withTexCoord1(GpuTriangleShading s, vec2 texCoord1At0, vec2 texCoord1At1, vec2 texCoord1At2) {
  s.texCoord1Vertices01 = make_vec4(texCoord1At0.x, texCoord1At0.y, texCoord1At1.x, texCoord1At1.y);
  s.texCoord1Vertex2 = make_vec4(texCoord1At2.x, texCoord1At2.y, 1.0f, 0.0f);
  return s;
}

// GpuTexture.info.w bits: wrap modes (2 bits each, s then t) and flags.
#define WP_TEXTURE_WRAP_REPEAT 0u
#define WP_TEXTURE_WRAP_CLAMP 1u
#define WP_TEXTURE_WRAP_MIRROR 2u
#define WP_TEXTURE_SRGB 16u     // texels are sRGB-encoded colour (decoded before filtering)
#define WP_TEXTURE_NEAREST 32u  // nearest texel instead of bilinear
#define WP_TEXTURE_TEXCOORD1 64u  // looked up with TEXCOORD_1 instead of TEXCOORD_0

// A texture as one material slot uses it (glTF textureInfo): the image and sampler, and the
// slot's texCoord set and KHR_texture_transform; 48 bytes.
//   info: x: first texel in the texel buffer, y: width, z: height, w: wrap and flags
//   uvTransformU, uvTransformV: xyz: the rows of the 2x3 matrix that takes (u, v, 1) to the
//     coordinates looked up (KHR_texture_transform's offset, rotation and scale); w: unused
#define WP_FIELDS_GpuTexture(F) \
  F(uvec4, info)                \
  F(vec4, uvTransformU)         \
  F(vec4, uvTransformV)
WP_RECORD(GpuTexture)
WP_FN uint textureFirstTexel(GpuTexture t) { return t.info.x; }
WP_FN uint textureWidth(GpuTexture t) { return t.info.y; }
WP_FN uint textureHeight(GpuTexture t) { return t.info.z; }
WP_FN uint textureWrapS(GpuTexture t) { return t.info.w & 3u; }
WP_FN uint textureWrapT(GpuTexture t) { return (t.info.w >> 2u) & 3u; }
WP_FN bool textureIsSrgb(GpuTexture t) { return (t.info.w & WP_TEXTURE_SRGB) != 0u; }
WP_FN bool textureIsNearest(GpuTexture t) { return (t.info.w & WP_TEXTURE_NEAREST) != 0u; }
WP_FN bool textureUsesTexCoord1(GpuTexture t) { return (t.info.w & WP_TEXTURE_TEXCOORD1) != 0u; }
WP_FN vec3 textureUvTransformU(GpuTexture t) { return make_vec3(t.uvTransformU.x, t.uvTransformU.y, t.uvTransformU.z); }
WP_FN vec3 textureUvTransformV(GpuTexture t) { return make_vec3(t.uvTransformV.x, t.uvTransformV.y, t.uvTransformV.z); }
// On TEXCOORD_0 without a transform; withTexCoords sets both.
WP_FN GpuTexture makeGpuTexture(uint firstTexel, uint width, uint height, uint wrapS, uint wrapT, bool srgb,
                                bool nearest) {
  GpuTexture t;
  uint flags = wrapS | (wrapT << 2u) | (srgb ? WP_TEXTURE_SRGB : 0u) | (nearest ? WP_TEXTURE_NEAREST : 0u);
  t.info = make_uvec4(firstTexel, width, height, flags);
  t.uvTransformU = make_vec4(1.0f, 0.0f, 0.0f, 0.0f);
  t.uvTransformV = make_vec4(0.0f, 1.0f, 0.0f, 0.0f);
  return t;
}
// The slot's coordinate set (TEXCOORD_1 or _0) and the rows of its transform.
WP_FN GpuTexture withTexCoords(GpuTexture t, bool texCoord1, vec3 uvTransformU, vec3 uvTransformV) {
  t.info.w = (t.info.w & ~WP_TEXTURE_TEXCOORD1) | (texCoord1 ? WP_TEXTURE_TEXCOORD1 : 0u);
  t.uvTransformU = make_vec4(uvTransformU.x, uvTransformU.y, uvTransformU.z, 0.0f);
  t.uvTransformV = make_vec4(uvTransformV.x, uvTransformV.y, uvTransformV.z, 0.0f);
  return t;
}

// One placed object: a mesh (bottom-level BVH) or an analytic sphere, 64 bytes.
//   worldToObject0..2: rows of the 3x4 world-to-object matrix (at shutter open if it moves)
//   info: x: WP_INSTANCE_*, y: BVH root node (mesh) or material (sphere), z: first light
//     index of this instance's emissive triangles (WP_INVALID: none sampled), w: WP_INVALID
//     if it stands still, else the index of its two motion keys in the instance buffer
//     (motion.h)
#define WP_FIELDS_GpuInstance(F) \
  F(vec4, worldToObject0)        \
  F(vec4, worldToObject1)        \
  F(vec4, worldToObject2)        \
  F(uvec4, info)
WP_RECORD(GpuInstance)
WP_FN uint instanceKind(GpuInstance inst) { return inst.info.x; }  // WP_INSTANCE_*
WP_FN uint instanceBvhRoot(GpuInstance inst) { return inst.info.y; }
WP_FN uint instanceSphereMaterial(GpuInstance inst) { return inst.info.y; }
WP_FN uint instanceFirstLight(GpuInstance inst) { return inst.info.z; }
WP_FN uint instanceMotionKeys(GpuInstance inst) { return inst.info.w; }
// An instance of kind `kind` (WP_INSTANCE_*) whose rows of the world-to-object matrix are
// row0..2, with its BVH root (mesh) or material (sphere), that is light-sampled from no
// light and stands still until withInstanceFirstLight and withInstanceMotionKeys say
// otherwise.
WP_FN GpuInstance makeGpuInstance(vec4 row0, vec4 row1, vec4 row2, uint kind, uint bvhRootOrMaterial) {
  GpuInstance inst;
  inst.worldToObject0 = row0;
  inst.worldToObject1 = row1;
  inst.worldToObject2 = row2;
  inst.info = make_uvec4(kind, bvhRootOrMaterial, WP_INVALID, WP_INVALID);
  return inst;
}
WP_FN GpuInstance withInstanceFirstLight(GpuInstance inst, uint firstLight) {
  inst.info.z = firstLight;
  return inst;
}
WP_FN GpuInstance withInstanceMotionKeys(GpuInstance inst, uint motionKeys) {
  inst.info.w = motionKeys;
  return inst;
}

// A moving instance's placement at shutter open and at shutter close is kept as two motion
// keys, stored after the placed instances in the instance buffer in GpuInstance records (so
// no binding is added): a TRS key holds the translation in worldToObject0.xyz, the rotation
// quaternion (x, y, z, w) in worldToObject1 and the scale in worldToObject2.xyz; a matrix key
// (a transform with shear) the rows of the 3x4 object-to-world matrix. info.x says which.
#define WP_MOTION_KEY_TRS 0u
#define WP_MOTION_KEY_MATRIX 1u
WP_FN uint motionKeyKind(GpuInstance key) { return key.info.x; }  // WP_MOTION_KEY_*
WP_FN vec4 motionKeyTranslation(GpuInstance key) { return key.worldToObject0; }  // xyz
WP_FN vec4 motionKeyRotation(GpuInstance key) { return key.worldToObject1; }
WP_FN vec4 motionKeyScale(GpuInstance key) { return key.worldToObject2; }  // xyz
WP_FN vec4 motionKeyRow0(GpuInstance key) { return key.worldToObject0; }
WP_FN vec4 motionKeyRow1(GpuInstance key) { return key.worldToObject1; }
WP_FN vec4 motionKeyRow2(GpuInstance key) { return key.worldToObject2; }
// rotation: the quaternion (x, y, z, w).
WP_FN GpuInstance makeTrsMotionKey(vec3 translation, vec4 rotation, vec3 scale) {
  GpuInstance key;
  key.worldToObject0 = make_vec4(translation.x, translation.y, translation.z, 0.0f);
  key.worldToObject1 = rotation;
  key.worldToObject2 = make_vec4(scale.x, scale.y, scale.z, 0.0f);
  key.info = make_uvec4(WP_MOTION_KEY_TRS, 0u, 0u, 0u);
  return key;
}
// row0..2: the rows of the 3x4 object-to-world matrix.
WP_FN GpuInstance makeMatrixMotionKey(vec4 row0, vec4 row1, vec4 row2) {
  GpuInstance key;
  key.worldToObject0 = row0;
  key.worldToObject1 = row1;
  key.worldToObject2 = row2;
  key.info = make_uvec4(WP_MOTION_KEY_MATRIX, 0u, 0u, 0u);
  return key;
}

// Infinite plane dot(n, p) = d, 32 bytes.
//   normalDistance: xyz: unit normal, w: d
//   info: x: material index
#define WP_FIELDS_GpuPlane(F) \
  F(vec4, normalDistance)     \
  F(uvec4, info)
WP_RECORD(GpuPlane)
WP_FN vec3 planeNormal(GpuPlane p) { return make_vec3(p.normalDistance.x, p.normalDistance.y, p.normalDistance.z); }
WP_FN float planeDistance(GpuPlane p) { return p.normalDistance.w; }
WP_FN uint planeMaterial(GpuPlane p) { return p.info.x; }
WP_FN GpuPlane makeGpuPlane(vec3 normal, float distance, uint material) {
  GpuPlane p;
  p.normalDistance = make_vec4(normal.x, normal.y, normal.z, distance);
  p.info = make_uvec4(material, 0u, 0u, 0u);
  return p;
}

// GpuMaterial.info.x: which BSDF the material has.
#define WP_MATERIAL_GLTF 0u     // glTF metallic-roughness mixture (shaders/common/material.h)
#define WP_MATERIAL_LAMBERT 1u  // ideal diffuse (extras.wavepath.bsdf = "lambert")
#define WP_MATERIAL_GLTF_DISNEY_DIFFUSE 2u  // the mixture with the seed's Disney diffuse base
                                            // (extras.wavepath.diffuse = "disney")
#define WP_MATERIAL_UNLIT 3u  // KHR_materials_unlit: glows with its base colour, scatters nothing

// A surface material, 224 bytes.
//   baseColor: rgb: linear base colour (albedo, metal F0, glass tint), a: alpha
//   emission: rgb: emitted radiance (factor * strength); w: 1 if double-sided, else 0
//   surface: x: metallic, y: perceptual roughness, z: ior, w: transmission
//   attenuation: rgb: KHR_materials_volume attenuationColor, w: attenuationDistance
//     (WP_FLT_MAX: no absorption)
//   info: x: WP_MATERIAL_*, y: base colour texture, z: metallic-roughness texture, w: normal
//     texture (WP_INVALID: none)
//   normalMap: x: the normal texture's scale, yzw: unused
//   emissiveMap: x: emissive texture (sRGB, multiplies `emission`; WP_INVALID: none), yzw:
//     unused
//   alphaInfo: x: WP_ALPHA_* (glTF alphaMode), y: asUint(alphaCutoff), zw: unused
// The layered extensions (material.h), white specular and no layers without them:
//   specular: rgb: KHR_materials_specular specularColorFactor, w: specularFactor
//   sheen: rgb: KHR_materials_sheen sheenColorFactor, w: sheenRoughnessFactor
//   clearcoat: x: KHR_materials_clearcoat clearcoatFactor, y: clearcoatRoughnessFactor,
//     z: the clearcoat normal texture's scale, w: unused
//   clearcoatNormal: xyz: the coat's unit normal in the local shading frame; packed as
//     (0, 0, 1), the shading normal, and set at the hit from the clearcoat normal texture
//   layerMaps: textures (WP_INVALID: none) x: specularTexture (its alpha), y:
//     specularColorTexture (sRGB), z: sheenColorTexture (sRGB), w: sheenRoughnessTexture
//     (its alpha)
//   clearcoatMaps: textures x: clearcoatTexture (red), y: clearcoatRoughnessTexture (green),
//     z: clearcoatNormalTexture, w: unused
#define WP_FIELDS_GpuMaterial(F) \
  F(vec4, baseColor)             \
  F(vec4, emission)              \
  F(vec4, surface)               \
  F(vec4, attenuation)           \
  F(uvec4, info)                 \
  F(vec4, normalMap)             \
  F(uvec4, emissiveMap)          \
  F(uvec4, alphaInfo)            \
  F(vec4, specular)              \
  F(vec4, sheen)                 \
  F(vec4, clearcoat)             \
  F(vec4, clearcoatNormal)       \
  F(uvec4, layerMaps)            \
  F(uvec4, clearcoatMaps)
WP_RECORD(GpuMaterial)
WP_FN uint materialKind(GpuMaterial m) { return m.info.x; }  // WP_MATERIAL_*
WP_FN float materialMetallic(GpuMaterial m) { return m.surface.x; }
WP_FN float materialTransmission(GpuMaterial m) { return m.surface.w; }
WP_FN vec3 materialSpecularColor(GpuMaterial m) { return make_vec3(m.specular.x, m.specular.y, m.specular.z); }
WP_FN float materialSpecularWeight(GpuMaterial m) { return m.specular.w; }
WP_FN vec3 materialSheenColor(GpuMaterial m) { return make_vec3(m.sheen.x, m.sheen.y, m.sheen.z); }
WP_FN float materialSheenRoughness(GpuMaterial m) { return m.sheen.w; }
WP_FN float materialClearcoat(GpuMaterial m) { return m.clearcoat.x; }
WP_FN float materialClearcoatRoughness(GpuMaterial m) { return m.clearcoat.y; }
WP_FN float materialClearcoatNormalScale(GpuMaterial m) { return m.clearcoat.z; }
WP_FN vec3 materialClearcoatNormal(GpuMaterial m) {
  return make_vec3(m.clearcoatNormal.x, m.clearcoatNormal.y, m.clearcoatNormal.z);
}

// A material's textures, slot by slot (WP_INVALID: none). Each slot reads through the scene's
// constant for it (WP_SCENE_*_TEXTURE, GpuScene::features): where no material of the scene's
// surfaces fills a slot, the slot reads as none in Vulkan's and OpenCL's stages, so its lookup
// compiles away. lavapipe ran every slot's lookup for every hit (docs/performance.md).
WP_FN uint materialBaseColorTexture(GpuMaterial m) { return WP_SCENE_BASE_COLOR_TEXTURE ? m.info.y : WP_INVALID; }
WP_FN uint materialMetallicRoughnessTexture(GpuMaterial m) {
  return WP_SCENE_METALLIC_ROUGHNESS_TEXTURE ? m.info.z : WP_INVALID;
}
WP_FN uint materialNormalTexture(GpuMaterial m) { return WP_SCENE_NORMAL_TEXTURE ? m.info.w : WP_INVALID; }
WP_FN uint materialEmissiveTexture(GpuMaterial m) { return WP_SCENE_EMISSIVE_TEXTURE ? m.emissiveMap.x : WP_INVALID; }
WP_FN uint materialSpecularTexture(GpuMaterial m) { return WP_SCENE_EXTENSION_TEXTURES ? m.layerMaps.x : WP_INVALID; }
WP_FN uint materialSpecularColorTexture(GpuMaterial m) {
  return WP_SCENE_EXTENSION_TEXTURES ? m.layerMaps.y : WP_INVALID;
}
WP_FN uint materialSheenColorTexture(GpuMaterial m) { return WP_SCENE_EXTENSION_TEXTURES ? m.layerMaps.z : WP_INVALID; }
WP_FN uint materialSheenRoughnessTexture(GpuMaterial m) {
  return WP_SCENE_EXTENSION_TEXTURES ? m.layerMaps.w : WP_INVALID;
}
WP_FN uint materialClearcoatTexture(GpuMaterial m) { return WP_SCENE_EXTENSION_TEXTURES ? m.clearcoatMaps.x : WP_INVALID; }
WP_FN uint materialClearcoatRoughnessTexture(GpuMaterial m) {
  return WP_SCENE_EXTENSION_TEXTURES ? m.clearcoatMaps.y : WP_INVALID;
}
WP_FN uint materialClearcoatNormalTexture(GpuMaterial m) {
  return WP_SCENE_EXTENSION_TEXTURES ? m.clearcoatMaps.z : WP_INVALID;
}

// GpuMaterial alpha modes (glTF alphaMode): what the base colour's alpha means.
#define WP_ALPHA_OPAQUE 0u  // nothing: the surface is opaque
#define WP_ALPHA_MASK 1u    // opaque where alpha >= alphaCutoff, absent elsewhere
#define WP_ALPHA_BLEND 2u   // a ray passes with probability 1 - alpha (alpha.h)
WP_FN uint materialAlphaMode(GpuMaterial m) { return m.alphaInfo.x; }
WP_FN float materialAlphaCutoff(GpuMaterial m) { return asFloat(m.alphaInfo.y); }

// What a material needs of the shade stage's code, as bits: ORed over the materials, the
// scene's features (GpuScene::features); none or some, its shade class (below). glTF's BRDF
// needs the microfacet code, its clear coat or sheen the layers, its transmission the glass,
// its metalness the metal lobe; ideal diffuse and unlit materials need none of them. (A
// texture only scales its factor, so a factor of 0 means none anywhere on the surface.)
#define WP_NEEDS_MICROFACET 1u
#define WP_NEEDS_LAYERS 2u
#define WP_NEEDS_TRANSMISSION 4u
#define WP_NEEDS_METAL 8u
WP_FN uint materialShadeNeeds(GpuMaterial m) {
  uint kind = materialKind(m);
  if (kind == WP_MATERIAL_LAMBERT || kind == WP_MATERIAL_UNLIT) {
    return 0u;
  }
  uint needs = WP_NEEDS_MICROFACET;
  if (materialClearcoat(m) > 0.0f || max(m.sheen.x, max(m.sheen.y, m.sheen.z)) > 0.0f) {
    needs |= WP_NEEDS_LAYERS;
  }
  if (materialTransmission(m) > 0.0f) {
    needs |= WP_NEEDS_TRANSMISSION;
  }
  if (materialMetallic(m) > 0.0f) {
    needs |= WP_NEEDS_METAL;
  }
  return needs;
}

// Whether a surface of material m emits light: an emission above 0 (the emissive factor; a
// texture only scales it) or unlit (integrator.h: its colour is emission). The triangle
// lights are the emitting triangles (packScene).
WP_FN bool materialEmits(GpuMaterial m) {
  return materialKind(m) == WP_MATERIAL_UNLIT || max(m.emission.x, max(m.emission.y, m.emission.z)) > 0.0f;
}

// Shade classes (Vulkan, shade.comp): in a scene with both, the misses and the hits on
// materials that need nothing (materialShadeNeeds: ideal diffuse, unlit) are shaded by a
// pipeline without glTF's BRDF, which defers the other hits to the deferred shade queue
// (queues.h) for a pipeline with it.
#define WP_SHADE_CLASS_DIFFUSE 0u
#define WP_SHADE_CLASS_MICROFACET 1u

// GpuLight.info.y: what the light is, in the low bits, and its flags above them.
#define WP_LIGHT_TRIANGLE 0u     // an emissive triangle (an area light)
#define WP_LIGHT_POINT 1u        // KHR_lights_punctual: a point
#define WP_LIGHT_SPOT 2u         // a point emitting into a cone
#define WP_LIGHT_DIRECTIONAL 3u  // a distant light (a sun) from one direction
#define WP_LIGHT_KIND_MASK 3u
#define WP_LIGHT_DOUBLE_SIDED 4u  // a triangle that emits on both sides (else the front only,
                                  // the side of cross(edge1, edge2))

// One light of next event estimation, with its alias-table entry for power-proportional
// selection (pick i = min(floor(u * n), n - 1), keep i if fract(u * n) < threshold, else take
// alias): an emissive triangle in world space, or a glTF punctual light, whose position and
// direction may move while the shutter is open. Read it through the accessors of lights.h.
// 96 bytes.
//   v0: triangle: xyz vertex 0, w area; punctual: xyz position at shutter open, w cos of a
//     spot's outer cone angle
//   edge1: triangle: xyz v1 - v0; punctual: xyz the unit direction it points (spot,
//     directional) at shutter open; w: probability of selecting this light
//   edge2: triangle: xyz v2 - v0; punctual: xyz position at shutter close; w: alias
//     threshold in [0, 1]
//   emission: rgb: radiance (triangle), radiant intensity in W/sr (point, spot) or
//     irradiance in W/m^2 (directional); w: luminance of the triangle's mean emitted
//     radiance (texture included), or of the intensity or irradiance
//   motion: punctual: xyz the direction at shutter close, w cos of a spot's inner cone
//     angle; unused by triangles
//   info: x: alias index, y: WP_LIGHT_* kind | WP_LIGHT_DOUBLE_SIDED, z: the triangle's
//     GpuTriangleShading (its vertices in the order of v0, edge1, edge2), w: its emissive
//     texture (WP_INVALID: none)
#define WP_FIELDS_GpuLight(F) \
  F(vec4, v0)                 \
  F(vec4, edge1)              \
  F(vec4, edge2)              \
  F(vec4, emission)           \
  F(vec4, motion)             \
  F(uvec4, info)
WP_RECORD(GpuLight)

// Settings of the sky, 32 bytes for a uniform or constant buffer.
WP_STRUCT(GpuEnvironment)
  float intensity;  // radiance multiplier
  float rotation;   // about +y, radians
  // Probability that next event estimation samples the sky rather than the emissive
  // triangles.
  float selectionProbability;
  float unused0;
  uint width;  // texels
  uint height;
  uint unused1;
  uint unused2;
WP_STRUCT_END(GpuEnvironment)

// Per-frame settings, a read-only storage buffer (OpenCL: a constant argument).
WP_STRUCT(RenderParams)
  ThinLens camera;     // optics and placement of the camera (thin_lens.h)
  GpuEnvironment sky;  // the sky seen by rays that leave the scene (environment.h)
  uint width;          // of the image, in pixels
  uint height;
  uint pixelCount;     // pixels traced: the region's (row-major)
  uint seed;
  uint maxBounces;     // counted as Cycles counts them (integrator.h)
  uint mode;           // WP_MODE_*
  uint rouletteStart;  // the first bounce at which Russian roulette may end a path
  uint lightCount;     // lights in the light table (triangles and punctual)
  uint planeCount;
  uint topLevel;       // the top level's root as a stack entry (GpuScene::topLevelEntry)
  uint instanceCount;  // placed instances
  uint maxPaths;       // paths of a pass at most: the length of each queue
  uint bsdfFlags;      // WP_BSDF_*
  float contributionClamp;  // biased clamp on what a path adds after its first vertex; 0: off
  uint lightSelection;      // WP_LIGHT_SELECTION_*
  uint punctualLightCount;  // punctual (delta) lights, the last of the light table
  // The pixels traced: first column and row, width and height (the whole image unless
  // --region, or a tile of it when it does not fit the device at once).
  uint regionX;
  uint regionY;
  uint regionWidth;
  uint regionHeight;
  // Adaptive sampling (accumulation.h): a pixel stops receiving samples once its estimated
  // relative error is below adaptiveThreshold (0: off), checked from adaptiveMinSamples on.
  float adaptiveThreshold;
  uint adaptiveMinSamples;
  uint samplerKind;  // WP_SAMPLER_* (sampler.h)
  // 1 where a ray can find emission: a surface emits, or the sky is not black. 0 (a scene lit
  // by lamps alone under a black sky: most glTF files from Blender) spares the last vertex's
  // ray, which could only find emission (sampleContinuation, integrator.h).
  uint emissionHittable;
  // 1 where the render keeps its feature passes (an EXR's albedo, normal and depth): shade
  // records them and accumulate sums them. 0 (a PNG, an EXR without passes):
  // neither, and the accumulation's feature layers stay zero (recordsFeaturePasses).
  uint featurePasses;
  // Cycles' Filter Glossy (glossyFloorRoughness, integrator.h): biased, roughens the glossy
  // lobes a path reaches after unlikely bounces; 0: off.
  float filterGlossy;
  uint unused1;
  uint unused2;
WP_STRUCT_END(RenderParams)

// Whether the render records feature passes. Vulkan builds the stages of a render without
// them with none of their code (WP_RENDER_FEATURE_PASSES false, prelude_glsl.h); C++ and
// OpenCL test the parameter.
WP_FN bool recordsFeaturePasses(RenderParams p) { return WP_RENDER_FEATURE_PASSES && p.featurePasses != 0u; }

// One path waiting to be traced: 64 bytes.
//   origin: xyz; w: asFloat(path slot in this pass)
//   direction: xyz: unit; w: solid-angle pdf of the BSDF sample (0: camera ray)
//   throughput: rgb; w: the path's shutter time in [0, 1) (motion blur)
//   state: x: the sampler's state (PathSamples), y: bounce of the vertex this ray will hit,
//     z: WP_RAY_* flags in the low 16 bits; in the high 16 the least pdf of the path's BSDF
//     samples so far (leastPdfBits, integrator.h; 0: none yet), w: the path's sample index
//     in its pixel
#define WP_FIELDS_PathRay(F) \
  F(vec4, origin)            \
  F(vec4, direction)         \
  F(vec4, throughput)        \
  F(uvec4, state)
WP_RECORD(PathRay)
WP_FN vec3 rayOrigin(PathRay r) { return make_vec3(r.origin.x, r.origin.y, r.origin.z); }
WP_FN uint rayPathSlot(PathRay r) { return asUint(r.origin.w); }
WP_FN vec3 rayDirection(PathRay r) { return make_vec3(r.direction.x, r.direction.y, r.direction.z); }
// The solid-angle pdf of the BSDF sample that chose the direction; 0 for camera rays and
// delta samples (nothing to weigh emission against).
WP_FN float rayBsdfPdf(PathRay r) { return r.direction.w; }
WP_FN vec3 rayThroughput(PathRay r) { return make_vec3(r.throughput.x, r.throughput.y, r.throughput.z); }
WP_FN float rayTime(PathRay r) { return r.throughput.w; }
WP_FN PathSamples rayPathSamples(PathRay r) {
  PathSamples p;
  p.state = r.state.x;
  p.sampleIndex = r.state.w;
  return p;
}
WP_FN uint rayBounce(PathRay r) { return r.state.y; }
// PathRay flags.
#define WP_RAY_FEATURES_TAKEN 1u  // the path's feature passes are recorded (PathFeatures)
WP_FN uint rayFlagsOf(PathRay r) { return r.state.z & 0xffffu; }
WP_FN bool rayFeaturesTaken(PathRay r) { return (rayFlagsOf(r) & WP_RAY_FEATURES_TAKEN) != 0u; }
WP_FN uint rayLeastPdfBits(PathRay r) { return r.state.z >> 16u; }
WP_FN PathRay makePathRay(vec3 origin, uint pathSlot, vec3 direction, float bsdfPdf, vec3 throughput, float time,
                          PathSamples samples, uint bounce, uint flags, uint leastPdfBits) {
  PathRay r;
  r.origin = make_vec4(origin.x, origin.y, origin.z, asFloat(pathSlot));
  r.direction = make_vec4(direction.x, direction.y, direction.z, bsdfPdf);
  r.throughput = make_vec4(throughput.x, throughput.y, throughput.z, time);
  r.state = make_uvec4(samples.state, bounce, flags | (leastPdfBits << 16u), samples.sampleIndex);
  return r;
}

// The feature passes of one path (what denoisers take besides the image; integrator.h says
// which vertex they come from): 32 bytes.
//   albedoDepth: rgb: albedo; w: depth of the camera ray's hit along the camera's axis
//   normal: xyz: world-space shading normal facing the ray, 0 for the sky; w: unused
#define WP_FIELDS_PathFeatures(F) \
  F(vec4, albedoDepth)            \
  F(vec4, normal)
WP_RECORD(PathFeatures)
WP_FN vec3 featureAlbedo(PathFeatures f) { return make_vec3(f.albedoDepth.x, f.albedoDepth.y, f.albedoDepth.z); }
WP_FN float featureDepth(PathFeatures f) { return f.albedoDepth.w; }
WP_FN vec3 featureNormal(PathFeatures f) { return make_vec3(f.normal.x, f.normal.y, f.normal.z); }
WP_FN PathFeatures withDepth(PathFeatures f, float depth) {
  f.albedoDepth.w = depth;
  return f;
}
WP_FN PathFeatures makePathFeatures(vec3 albedo, vec3 normal, float depth) {
  PathFeatures f;
  f.albedoDepth = make_vec4(albedo.x, albedo.y, albedo.z, depth);
  f.normal = make_vec4(normal.x, normal.y, normal.z, 0.0f);
  return f;
}

// Closest hit of the PathRay at the same queue position: 16 bytes.
//   hit: x: asUint(t) (WP_INVALID: miss), y: instance or plane index | WP_HIT_PLANE, z:
//     primitive (global triangle index), w: unused
#define WP_FIELDS_HitRecord(F) \
  F(uvec4, hit)
WP_RECORD(HitRecord)
#define WP_HIT_PLANE 0x80000000u
WP_FN bool hitIsMiss(HitRecord h) { return h.hit.x == WP_INVALID; }
WP_FN float hitDistance(HitRecord h) { return asFloat(h.hit.x); }
WP_FN uint hitInstanceField(HitRecord h) { return h.hit.y; }  // instance, or plane | WP_HIT_PLANE
WP_FN uint hitPrimitive(HitRecord h) { return h.hit.z; }
// A hit at distance t, or a miss where instanceField is WP_INVALID.
WP_FN HitRecord makeHitRecord(float t, uint instanceField, uint primitive) {
  HitRecord h;
  h.hit = make_uvec4(instanceField == WP_INVALID ? WP_INVALID : asUint(t), instanceField, primitive, 0u);
  return h;
}

// Next-event-estimation shadow ray: 48 bytes.
//   origin: xyz; w: asFloat(path slot)
//   direction: xyz: unit; w: distance to the light sample (exclusive)
//   contribution: rgb: radiance added to the path if unoccluded; w: the path's shutter time
#define WP_FIELDS_ShadowRay(F) \
  F(vec4, origin)              \
  F(vec4, direction)           \
  F(vec4, contribution)
WP_RECORD(ShadowRay)
WP_FN vec3 shadowRayOrigin(ShadowRay s) { return make_vec3(s.origin.x, s.origin.y, s.origin.z); }
WP_FN uint shadowRayPathSlot(ShadowRay s) { return asUint(s.origin.w); }
WP_FN vec3 shadowRayDirection(ShadowRay s) { return make_vec3(s.direction.x, s.direction.y, s.direction.z); }
WP_FN float shadowRayLength(ShadowRay s) { return s.direction.w; }
WP_FN vec3 shadowRayContribution(ShadowRay s) {
  return make_vec3(s.contribution.x, s.contribution.y, s.contribution.z);
}
WP_FN float shadowRayTime(ShadowRay s) { return s.contribution.w; }
WP_FN ShadowRay makeShadowRay(vec3 origin, uint pathSlot, vec3 direction, float rayLength, vec3 contribution,
                              float time) {
  ShadowRay s;
  s.origin = make_vec4(origin.x, origin.y, origin.z, asFloat(pathSlot));
  s.direction = make_vec4(direction.x, direction.y, direction.z, rayLength);
  s.contribution = make_vec4(contribution.x, contribution.y, contribution.z, time);
  return s;
}

// Queue sizes and indirect dispatch arguments, written on the GPU. Kernels address it as a
// flat uint array (atomics need a plain uint lvalue) through the word indices below.
WP_STRUCT(QueueCounters)
  uvec4 counts;           // x, y: ray queues 0 and 1; z, w: shadow queues of even/odd bounces
  uvec4 totals;           // x: extension rays traced this pass, y: shadow rays
  uvec4 extendDispatch;   // xyz: VkDispatchIndirectCommand for extend and shade
  uvec4 connectDispatch;  // xyz: VkDispatchIndirectCommand for connect
  uvec4 deferredShades;   // x: the deferred shade queue; yzw: unused
  uvec4 deferredShadeDispatch;  // xyz: VkDispatchIndirectCommand for shade over it
WP_STRUCT_END(QueueCounters)
#define WP_COUNTER_RAYS 0u            // + queue (0 or 1)
#define WP_COUNTER_SHADOW_RAYS 2u     // + bounce parity
#define WP_COUNTER_TOTAL_RAYS 4u
#define WP_COUNTER_TOTAL_SHADOW_RAYS 5u
#define WP_COUNTER_EXTEND_DISPATCH 8u
#define WP_COUNTER_CONNECT_DISPATCH 12u
#define WP_COUNTER_DEFERRED_SHADES 16u
#define WP_COUNTER_DEFERRED_SHADE_DISPATCH 20u
#define WP_COUNTER_WORDS 24u
WP_FN uint tracedRays(QueueCounters c) { return c.totals.x; }
WP_FN uint tracedShadowRays(QueueCounters c) { return c.totals.y; }

// Per-dispatch constants (Vulkan push constants, OpenCL kernel arguments). A pass traces
// `pathCount` paths: path slot i is pixel (firstPixel + i) % pixels of sample
// firstSample + (firstPixel + i) / pixels, so a pass may span several samples of a small
// image while every slot of one pixel is accumulated in sample order.
WP_STRUCT(PassConstants)
  uint firstPixel;
  uint firstSample;
  uint pathCount;
  uint bounce;  // of the extend, shade, advance or connect it is passed to
WP_STRUCT_END(PassConstants)
// PassConstants.bounce of the advance that runs right after generate (sizeFirstBounce).
#define WP_AFTER_GENERATE 0xffffffffu

WP_END

#endif
