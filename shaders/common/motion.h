// Motion blur: an instance's placement at a time inside the shutter, interpolated between
// its keys at shutter open and close, the same code on the host (tests) and both backends.
#ifndef WP_MOTION_H
#define WP_MOTION_H

#include "binding_table.h"
#include "instance.h"


WP_BEGIN

// An object-to-world transform as the three rows of its 3x4 matrix.
WP_STRUCT(AffineRows)
  vec4 row0;
  vec4 row1;
  vec4 row2;
WP_STRUCT_END(AffineRows)

// Spherical linear interpolation of unit quaternions (x, y, z, w) that the packer put in the
// same hemisphere (dot >= 0), so the shorter arc is taken. Nearly equal ones are lerped and
// normalized, where slerp's sin(theta) in the denominator would lose precision.
WP_FN vec4 slerpQuaternion(vec4 a, vec4 b, float u) {
  float cosTheta = min(dot(a, b), 1.0f);
  if (cosTheta > 0.9995f) {
    return normalize(a + (b - a) * u);
  }
  float theta = acos(cosTheta);
  float s = sin(theta);
  return a * (sin((1.0f - u) * theta) / s) + b * (sin(u * theta) / s);
}

// T R S as matrix rows: row r is (R[r][c] * scale[c], translation[r]).
WP_FN AffineRows trsRows(vec3 t, vec4 q, vec3 s) {
  float xx = q.x * q.x, yy = q.y * q.y, zz = q.z * q.z;
  float xy = q.x * q.y, xz = q.x * q.z, yz = q.y * q.z;
  float wx = q.w * q.x, wy = q.w * q.y, wz = q.w * q.z;
  AffineRows m;
  m.row0 = make_vec4((1.0f - 2.0f * (yy + zz)) * s.x, 2.0f * (xy - wz) * s.y, 2.0f * (xz + wy) * s.z, t.x);
  m.row1 = make_vec4(2.0f * (xy + wz) * s.x, (1.0f - 2.0f * (xx + zz)) * s.y, 2.0f * (yz - wx) * s.z, t.y);
  m.row2 = make_vec4(2.0f * (xz - wy) * s.x, 2.0f * (yz + wx) * s.y, (1.0f - 2.0f * (xx + yy)) * s.z, t.z);
  return m;
}

// The object-to-world transform at normalized shutter time u in [0, 1] from the keys at open
// and close (layout.h, GpuInstance of a motion key): translation and scale linear, rotation
// by slerp; keys of a transform with shear hold matrix rows, lerped component-wise.
WP_FN AffineRows objectToWorldAt(GpuInstance open, GpuInstance close, float u) {
  if (motionKeyKind(open) == WP_MOTION_KEY_MATRIX) {
    AffineRows m;
    m.row0 = motionKeyRow0(open) + (motionKeyRow0(close) - motionKeyRow0(open)) * u;
    m.row1 = motionKeyRow1(open) + (motionKeyRow1(close) - motionKeyRow1(open)) * u;
    m.row2 = motionKeyRow2(open) + (motionKeyRow2(close) - motionKeyRow2(open)) * u;
    return m;
  }
  vec4 t = motionKeyTranslation(open) + (motionKeyTranslation(close) - motionKeyTranslation(open)) * u;
  vec4 s = motionKeyScale(open) + (motionKeyScale(close) - motionKeyScale(open)) * u;
  return trsRows(make_vec3(t.x, t.y, t.z), slerpQuaternion(motionKeyRotation(open), motionKeyRotation(close), u),
                 make_vec3(s.x, s.y, s.z));
}

// The instance record `inst` with its world-to-object rows replaced by the inverse of `m`
// (the 3x3 part by cofactors over the determinant, then the translation).
WP_FN GpuInstance instanceWithTransform(GpuInstance inst, AffineRows m) {
  Cofactors c = cofactorsOfRows(make_vec3(m.row0.x, m.row0.y, m.row0.z), make_vec3(m.row1.x, m.row1.y, m.row1.z),
                                 make_vec3(m.row2.x, m.row2.y, m.row2.z));
  float invDet = 1.0f / c.determinant;
  // The inverse's columns are c0, c1, c2 over the determinant; its rows are read across them.
  vec3 i0 = make_vec3(c.c0.x, c.c1.x, c.c2.x) * invDet;
  vec3 i1 = make_vec3(c.c0.y, c.c1.y, c.c2.y) * invDet;
  vec3 i2 = make_vec3(c.c0.z, c.c1.z, c.c2.z) * invDet;
  vec3 t = make_vec3(m.row0.w, m.row1.w, m.row2.w);
  inst.worldToObject0 = make_vec4(i0.x, i0.y, i0.z, -dot(i0, t));
  inst.worldToObject1 = make_vec4(i1.x, i1.y, i1.z, -dot(i1, t));
  inst.worldToObject2 = make_vec4(i2.x, i2.y, i2.z, -dot(i2, t));
  return inst;
}

// Instance `i` as placed at normalized shutter time u: its own record when it stands still
// (the static path reads nothing more), else the record with the interpolated transform.
// Only builds with WP_MOTION_BLUR defined look at the keys: the backends compile the stages
// that call this twice and run the build without it where nothing moves, because the branch,
// untaken but inside the traversal loop, cost still scenes 12% on lavapipe
// (docs/motion-blur.md). The host code (C++) always has it.
WP_FN GpuInstance instanceAt(WP_BUFFERS uint i, float u) {
  GpuInstance inst = WP_LOAD(instances, i);
#ifdef WP_MOTION_BLUR
  uint keys = instanceMotionKeys(inst);
  if (keys != WP_INVALID) {
    inst = instanceWithTransform(inst, objectToWorldAt(WP_LOAD(instances, keys), WP_LOAD(instances, keys + 1u), u));
  }
#endif
  return inst;
}

WP_END

#endif
