// Reconstructs the surface at a hit (position, geometric normal, material, light index)
// from the hit record and the scene buffers.
#ifndef WP_SURFACE_H
#define WP_SURFACE_H

#include "binding_table.h"
#include "instance.h"
#include "motion.h"

WP_BEGIN


// The texture coordinate sets at a point, for texture lookups (texture.h): each slot picks its
// set and transforms it.
WP_STRUCT(TexCoords)
  vec2 set0;     // TEXCOORD_0, if hasSet0
  vec2 set1;     // TEXCOORD_1, if hasSet1
  bool hasSet0;
  bool hasSet1;
WP_STRUCT_END(TexCoords)

WP_STRUCT(SurfaceHit)
  vec3 position;
  vec3 normal;         // unit geometric normal, front side (counter-clockwise winding, outside)
  vec3 shadingNormal;  // unit interpolated vertex normal on the front side; `normal` if none
  TexCoords texCoords; // at the hit; none on spheres and planes
  vec4 color;          // COLOR_0 at the hit (white without)
  vec3 tangent;        // unit world-space tangent-space +X (normal mapping): glTF TANGENT,
                       // or else the triangle's dP/du; zero when there is neither
  vec3 bitangent;      // unit world-space +Y, "up" in the image: the TANGENT's bitangent,
                       // or else -dP/dv; zero with the tangent
  uint material;
  uint light;     // index into the light buffer, WP_INVALID if not a sampled light
WP_STRUCT_END(SurfaceHit)

// Four bytes (r in the low one) as values in [0, 1].
WP_FN vec4 unpackUnorm8(uint word) {
  return make_vec4(toFloat(word & 255u), toFloat((word >> 8u) & 255u), toFloat((word >> 16u) & 255u),
                   toFloat(word >> 24u)) *
         (1.0f / 255.0f);
}

// Barycentrics (of vertices 1 and 2) of an object-space point on the triangle's plane,
// recomputed here rather than carried from the traversal, which stays lean.
WP_FN vec2 barycentricsAt(GpuTriangle tri, vec3 p) {
  vec3 e1 = triangleEdge1(tri);
  vec3 e2 = triangleEdge2(tri);
  vec3 d = p - triangleVertex0(tri);
  float d00 = dot(e1, e1);
  float d01 = dot(e1, e2);
  float d11 = dot(e2, e2);
  float d20 = dot(d, e1);
  float d21 = dot(d, e2);
  float denominator = d00 * d11 - d01 * d01;
  if (!(denominator > 0.0f)) {
    return make_vec2(0.0f, 0.0f);
  }
  return make_vec2((d11 * d20 - d01 * d21) / denominator, (d00 * d21 - d01 * d20) / denominator);
}

// TEXCOORD_0 at barycentrics b (of vertices 1 and 2) of a triangle; hasUv(shading) says
// whether the mesh has it.
WP_FN vec2 uvAt(GpuTriangleShading shading, vec2 b) {
  return vertexUv0(shading) * (1.0f - b.x - b.y) + vertexUv1(shading) * b.x + vertexUv2(shading) * b.y;
}

// Both texture coordinate sets at barycentrics b of a triangle.
WP_FN TexCoords texCoordsAt(GpuTriangleShading shading, vec2 b) {
  TexCoords c;
  c.set0 = uvAt(shading, b);
  c.set1 = vertexTexCoord1At0(shading) * (1.0f - b.x - b.y) + vertexTexCoord1At1(shading) * b.x +
           vertexTexCoord1At2(shading) * b.y;
  c.hasSet0 = hasUv(shading);
  c.hasSet1 = hasTexCoord1(shading);
  return c;
}

// No texture coordinates (spheres, planes).
WP_FN TexCoords noTexCoords() {
  TexCoords c;
  c.set0 = make_vec2(0.0f, 0.0f);
  c.set1 = c.set0;
  c.hasSet0 = false;
  c.hasSet1 = false;
  return c;
}

// COLOR_0 (RGBA, white without) at barycentrics b (of vertices 1 and 2) of a triangle.
WP_FN vec4 colorAt(GpuTriangleShading shading, vec2 b) {
  return unpackUnorm8(vertexColor0(shading)) * (1.0f - b.x - b.y) + unpackUnorm8(vertexColor1(shading)) * b.x +
         unpackUnorm8(vertexColor2(shading)) * b.y;
}

// The material of the surface a hit reached (hitInstanceField, hitPrimitive), without
// reconstructing the surface: surfaceAt's, and what Vulkan's first shade pipeline sorts the
// hits into shade classes by (shade.comp). An instance's kind and material do not move.
WP_FN uint hitMaterial(WP_BUFFERS uint instanceField, uint primitive) {
  if (WP_SCENE_PLANES && (instanceField & WP_HIT_PLANE) != 0u) {
    return planeMaterial(WP_LOAD(planes, instanceField & ~WP_HIT_PLANE));
  }
  GpuInstance inst = WP_LOAD(instances, instanceField);
  if (WP_SCENE_SPHERES && instanceKind(inst) == WP_INSTANCE_SPHERE) {
    return instanceSphereMaterial(inst);
  }
  return triangleMaterial(WP_LOAD(triangles, primitive));
}

// `instanceField` and `primitive` are hitInstanceField and hitPrimitive of a hit at the
// normalized shutter time `time` the ray was traced at (moving instances are placed then).
WP_FN_INLINED SurfaceHit surfaceAt(WP_BUFFERS uint instanceField, uint primitive, vec3 position, float time) {
  SurfaceHit s;
  s.position = position;
  s.light = WP_INVALID;
  s.texCoords = noTexCoords();
  s.color = make_vec4(1.0f, 1.0f, 1.0f, 1.0f);
  s.tangent = make_vec3(1.0f, 0.0f, 0.0f);
  s.bitangent = make_vec3(0.0f, 1.0f, 0.0f);
  s.material = hitMaterial(WP_BUFFERS_ARG instanceField, primitive);
  if (WP_SCENE_PLANES && (instanceField & WP_HIT_PLANE) != 0u) {
    GpuPlane plane = WP_LOAD(planes, instanceField & ~WP_HIT_PLANE);
    s.normal = planeNormal(plane);
    s.shadingNormal = s.normal;
    return s;
  }
  GpuInstance inst = instanceAt(WP_BUFFERS_ARG instanceField, time);
  if (WP_SCENE_SPHERES && instanceKind(inst) == WP_INSTANCE_SPHERE) {
    s.normal = normalToWorld(inst, pointToObject(inst, position));
    s.shadingNormal = s.normal;
    return s;
  }
  GpuTriangle tri = WP_LOAD(triangles, primitive);
  vec3 e1 = triangleEdge1(tri);
  vec3 e2 = triangleEdge2(tri);
  s.normal = normalToWorld(inst, cross(e1, e2));
  s.shadingNormal = s.normal;
  GpuTriangleShading shading = WP_LOAD(triangleShading, primitive);
  vec2 b = barycentricsAt(tri, pointToObject(inst, position));
  vec3 n = vertexNormal0(shading) * (1.0f - b.x - b.y) + vertexNormal1(shading) * b.x + vertexNormal2(shading) * b.y;
  s.texCoords = texCoordsAt(shading, b);
  s.color = colorAt(shading, b);
  // The file's TANGENT (glTF: bitangent = w cross(normal, tangent), in object space, so a
  // mirroring instance transform mirrors it along with the rest), else the triangle's uv
  // gradient: [e1 e2] = [dP/du dP/dv] [du1 du2; dv1 dv2].
  vec4 t = vertexTangent0(shading) * (1.0f - b.x - b.y) + vertexTangent1(shading) * b.x +
           vertexTangent2(shading) * b.y;
  vec3 tangent = make_vec3(t.x, t.y, t.z);
  vec3 bitangent = cross(n, tangent) * (t.w < 0.0f ? -1.0f : 1.0f);
  vec2 uv0 = vertexUv0(shading);
  vec2 uv1 = vertexUv1(shading);
  vec2 uv2 = vertexUv2(shading);
  float du1 = uv1.x - uv0.x;
  float du2 = uv2.x - uv0.x;
  float dv1 = uv1.y - uv0.y;
  float dv2 = uv2.y - uv0.y;
  float determinant = du1 * dv2 - du2 * dv1;
  if (dot(tangent, tangent) > 1e-12f && dot(bitangent, bitangent) > 1e-12f) {
    s.tangent = directionToWorld(inst, tangent);
    s.bitangent = directionToWorld(inst, bitangent);
  } else if (s.texCoords.hasSet0 && determinant != 0.0f) {
    s.tangent = directionToWorld(inst, (e1 * dv2 - e2 * dv1) / determinant);
    s.bitangent = -directionToWorld(inst, (e2 * du1 - e1 * du2) / determinant);
  } else {
    s.tangent = make_vec3(0.0f, 0.0f, 0.0f);
    s.bitangent = make_vec3(0.0f, 0.0f, 0.0f);
  }
  if (dot(n, n) > 1e-12f) {
    // Vertex normals on the back of the face (bad data) are taken as facing the front.
    vec3 world = normalToWorld(inst, n);
    s.shadingNormal = dot(world, s.normal) >= 0.0f ? world : -world;
  }
  uint emitter = triangleEmitter(tri);
  uint firstLight = instanceFirstLight(inst);
  s.light = emitter == WP_INVALID || firstLight == WP_INVALID ? WP_INVALID : firstLight + emitter;
  return s;
}

// Moves a ray origin off the surface along the side of `normal` it leaves from, by a few
// floating-point ulps relative to the position's magnitude (Waechter & Binder, "A Fast and
// Robust Method for Avoiding Self-Intersection", Ray Tracing Gems 2019), so secondary rays
// neither re-hit their own surface nor tunnel through thin geometry at any scene scale.
WP_FN float offsetCoordinate(float p, float n) {
  int steps = toInt(256.0f * n);
  uint bits = asUint(p) + toUint(p < 0.0f ? -steps : steps);
  return fabs(p) < 0.03125f ? p + n * 1.52587890625e-5f : asFloat(bits);
}

WP_FN vec3 offsetRayOrigin(vec3 p, vec3 normal, vec3 direction) {
  vec3 n = dot(normal, direction) >= 0.0f ? normal : -normal;
  return make_vec3(offsetCoordinate(p.x, n.x), offsetCoordinate(p.y, n.y), offsetCoordinate(p.z, n.z));
}

WP_END

#endif
