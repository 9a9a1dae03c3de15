// Ray intersection routines (box slabs, triangle, unit sphere, plane) shared by the GPU
// traversal and the C++ tests.
#ifndef WP_INTERSECT_H
#define WP_INTERSECT_H

#include "portable.h"

// Stand-in for a zero direction component before inverting it: 1/x stays finite, and so do
// the slab distances of any box within 1e18 of the origin (GLSL min/max with NaN is undefined).
#define WP_TINY_DIRECTION 1e-20f
// Relative widening of a slab interval, 1 + 2 * gamma(3) (Ize 2013), so that rounding never
// makes a ray miss a box that it touches.
#define WP_SLAB_PADDING 1.00000036f

WP_BEGIN

// 1 / d, with |d| below WP_TINY_DIRECTION replaced by that tiny value of the same sign.
WP_FN float slabInverse(float d) {
  return 1.0f / (fabs(d) > WP_TINY_DIRECTION ? d : (d < 0.0f ? -WP_TINY_DIRECTION : WP_TINY_DIRECTION));
}

// Componentwise 1 / direction for the slab test (traverse.h), finite for every direction.
WP_FN vec3 rayInverseDirection(vec3 direction) {
  return make_vec3(slabInverse(direction.x), slabInverse(direction.y), slabInverse(direction.z));
}

// Moller-Trumbore ray/triangle test, both faces, with the division deferred to the hit.
// Returns t if the ray hits the triangle v0, v0 + edge1, v0 + edge2 at 0 < t < tMax, else
// tMax. Degenerate triangles and rays in the triangle's plane never hit.
WP_FN float intersectTriangle(vec3 origin, vec3 direction, vec3 v0, vec3 edge1, vec3 edge2, float tMax) {
  vec3 p = cross(direction, edge2);
  float det = dot(edge1, p);
  // Folding the sign of det into u, v, t lets one set of comparisons serve both faces.
  float faceSign = det < 0.0f ? -1.0f : 1.0f;
  float absDet = det * faceSign;
  vec3 s = origin - v0;
  float u = dot(s, p) * faceSign;
  vec3 q = cross(s, edge1);
  float v = dot(direction, q) * faceSign;
  float tScaled = dot(edge2, q) * faceSign;
  bool inside = absDet > 0.0f && u >= 0.0f && v >= 0.0f && u + v <= absDet;
  float t = tScaled / (inside ? absDet : 1.0f);
  return inside && t > 0.0f && t < tMax ? t : tMax;
}

// Ray against the unit sphere at the origin, for object-space rays whose direction need not
// be unit length (t is in units of that direction, so it equals the world-space t). Returns
// the nearest root in (0, tMax), also when the ray starts inside, else tMax. Requires a
// non-zero direction.
WP_FN float intersectUnitSphere(vec3 origin, vec3 direction, float tMax) {
  float a = dot(direction, direction);
  // Roots as closest approach +- half chord: no catastrophic b^2 - ac for far-away origins.
  float tClosest = -dot(origin, direction) / a;
  vec3 closest = origin + direction * tClosest;
  float h2 = 1.0f - dot(closest, closest);
  float halfChord = sqrt(max(h2, 0.0f) / a);
  float tNear = tClosest - halfChord;
  float t = tNear > 0.0f ? tNear : tClosest + halfChord;
  return h2 >= 0.0f && t > 0.0f && t < tMax ? t : tMax;
}

// Ray against the plane dot(normal, p) = planeDistance. Returns t in (0, tMax), else tMax (also
// for rays parallel to the plane).
WP_FN float intersectPlane(vec3 normal, float planeDistance, vec3 origin, vec3 direction, float tMax) {
  float denom = dot(normal, direction);
  float t = (planeDistance - dot(normal, origin)) / (denom != 0.0f ? denom : 1.0f);
  return denom != 0.0f && t > 0.0f && t < tMax ? t : tMax;
}

WP_END

#endif
