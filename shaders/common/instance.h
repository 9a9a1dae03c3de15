// An instance's placement as the rows of its 3x4 world-to-object matrix: points, directions
// and normals taken between world and object space, and the cofactors that invert a 3x3
// matrix (motion.h inverts a whole placement with them).
#ifndef WP_INSTANCE_H
#define WP_INSTANCE_H

#include "binding_table.h"

WP_BEGIN

// The cofactor columns of the 3x3 matrix with rows r0, r1, r2 and its determinant: its
// inverse has columns c0, c1, c2 over the determinant.
WP_STRUCT(Cofactors)
  vec3 c0;
  vec3 c1;
  vec3 c2;
  float determinant;
WP_STRUCT_END(Cofactors)

WP_FN Cofactors cofactorsOfRows(vec3 r0, vec3 r1, vec3 r2) {
  Cofactors c;
  c.c0 = cross(r1, r2);
  c.c1 = cross(r2, r0);
  c.c2 = cross(r0, r1);
  c.determinant = dot(r0, c.c0);
  return c;
}

// World-to-object transform of a point and of a direction by the instance's rows. The
// direction keeps its length, so object-space t values along a ray equal world-space ones.
WP_FN vec3 pointToObject(GpuInstance inst, vec3 p) {
  vec4 q = make_vec4(p.x, p.y, p.z, 1.0f);
  return make_vec3(dot(inst.worldToObject0, q), dot(inst.worldToObject1, q), dot(inst.worldToObject2, q));
}
WP_FN vec3 directionToObject(GpuInstance inst, vec3 d) {
  vec4 q = make_vec4(d.x, d.y, d.z, 0.0f);
  return make_vec3(dot(inst.worldToObject0, q), dot(inst.worldToObject1, q), dot(inst.worldToObject2, q));
}

// An object-space normal in world space, unit length: the inverse transpose, which for a
// world-to-object matrix M is transpose(M).
WP_FN vec3 normalToWorld(GpuInstance inst, vec3 n) {
  vec3 r0 = make_vec3(inst.worldToObject0.x, inst.worldToObject0.y, inst.worldToObject0.z);
  vec3 r1 = make_vec3(inst.worldToObject1.x, inst.worldToObject1.y, inst.worldToObject1.z);
  vec3 r2 = make_vec3(inst.worldToObject2.x, inst.worldToObject2.y, inst.worldToObject2.z);
  return normalize(r0 * n.x + r1 * n.y + r2 * n.z);
}

// An object-space direction in world space, unit length: the inverse of the world-to-object
// matrix M applied to d, as the cofactor columns over det(M).
WP_FN vec3 directionToWorld(GpuInstance inst, vec3 d) {
  vec3 r0 = make_vec3(inst.worldToObject0.x, inst.worldToObject0.y, inst.worldToObject0.z);
  vec3 r1 = make_vec3(inst.worldToObject1.x, inst.worldToObject1.y, inst.worldToObject1.z);
  vec3 r2 = make_vec3(inst.worldToObject2.x, inst.worldToObject2.y, inst.worldToObject2.z);
  Cofactors c = cofactorsOfRows(r0, r1, r2);
  return normalize((c.c0 * d.x + c.c1 * d.y + c.c2 * d.z) / c.determinant);
}

WP_END

#endif
