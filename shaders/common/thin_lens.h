// Thin-lens camera: primary rays from a point on a circular or N-blade aperture through the
// plane in focus, and the circle of confusion the thin-lens equation predicts.
#ifndef WP_THIN_LENS_H
#define WP_THIN_LENS_H

#include "sampling.h"

WP_BEGIN

// Optics of a thin-lens camera, 80 bytes of vec4s so it can sit in a uniform buffer. Lengths
// are in scene units (metres for glTF): focal length, film and aperture too, so a 50 mm lens
// is 0.05. The film is a virtual sensor in front of the lens, so the picture is upright.
WP_STRUCT(ThinLens)
  vec4 position;  // xyz: centre of the lens; w: focal length f
  vec4 right;     // xyz: unit image x axis; w: half the film width
  vec4 up;        // xyz: unit image y axis (up in the picture); w: half the film height
  vec4 forward;   // xyz: unit optical axis; w: focus distance D > f, from the lens along it
  vec4 aperture;  // x: aperture radius f / (2 N), 0 for a pinhole; y: blade count, 0 for a
                  // circle, else >= 3; z: angle of the first polygon corner from `right`
                  // towards `up`, radians; w: 1 for an orthographic camera (see
                  // makeOrthographicLens), else 0
WP_STRUCT_END(ThinLens)

WP_STRUCT(CameraRay)
  vec3 origin;     // on the aperture
  vec3 direction;  // unit
WP_STRUCT_END(CameraRay)

// The default sensor, full-frame 35 mm film, in metres.
#define WP_SENSOR_WIDTH 0.036f
#define WP_SENSOR_HEIGHT 0.024f

// Half extents of the film actually exposed: the largest rectangle of the image's aspect
// ratio (width / height) centred on the sensor, as a camera crops its sensor for another
// format. A 16:9 image keeps the full 36 mm width of a 36 x 24 mm sensor; a square one keeps
// its 24 mm height.
WP_FN vec2 filmHalfExtent(vec2 sensorSize, float imageAspect) {
  float width = min(sensorSize.x, sensorSize.y * imageAspect);
  return make_vec2(0.5f * width, 0.5f * width / imageAspect);
}

// The focal length at which a film of half height `filmHalfHeight` sees the vertical field
// of view `yfov` (radians) when focused at infinity: how a glTF camera's yfov becomes a lens.
WP_FN float focalLengthForFieldOfView(float yfov, float filmHalfHeight) {
  return filmHalfHeight / tan(0.5f * yfov);
}

// Distance V behind the lens at which a point at distance D (> f) comes into focus, from the
// thin-lens equation 1/f = 1/D + 1/V. The film sits there, so focusing closer narrows the
// field of view slightly, as real lenses "breathe".
WP_FN float imageDistance(float focalLength, float focusDistance) {
  // f D / (D - f), written so that focusing at infinity (D = WP_FLT_MAX) does not overflow.
  return focalLength / (1.0f - focalLength / focusDistance);
}

// Diameter, on the film, of the blur disc of a point at distance `objectDistance` when a
// lens of focal length f with an aperture `apertureDiameter` wide (f / N) is focused at
// `focusDistance` S1 (distances from the lens along its axis, > f):
//   c = A |S2 - S1| / S2 * f / (S1 - f).
// It follows from similar triangles on the cone of light converging behind the lens to the
// image of the point, cut by the film at imageDistance(f, S1).
WP_FN float circleOfConfusion(float apertureDiameter, float focalLength, float focusDistance,
                              float objectDistance) {
  return apertureDiameter * fabs(objectDistance - focusDistance) / objectDistance * focalLength /
         (focusDistance - focalLength);
}

// A camera at `position` looking along `forward` (unit) with `up` (any vector not parallel to
// forward) towards the top of the picture, a circular aperture of f-number N, focused at
// `focusDistance` (> focalLength). filmHalf comes from filmHalfExtent.
WP_FN ThinLens makeThinLens(vec3 position, vec3 forward, vec3 up, vec2 filmHalf, float focalLength, float fNumber,
                            float focusDistance) {
  vec3 right = normalize(cross(forward, up));
  vec3 trueUp = cross(right, forward);
  ThinLens lens;
  lens.position = make_vec4(position.x, position.y, position.z, focalLength);
  lens.right = make_vec4(right.x, right.y, right.z, filmHalf.x);
  lens.up = make_vec4(trueUp.x, trueUp.y, trueUp.z, filmHalf.y);
  lens.forward = make_vec4(forward.x, forward.y, forward.z, focusDistance);
  lens.aperture = make_vec4(0.5f * focalLength / fNumber, 0.0f, 0.0f, 0.0f);
  return lens;
}

// An orthographic camera: parallel rays along `forward` from a view rectangle 2 halfExtent
// wide and high (scene units) centred on `position`. It keeps the thin lens's record, with
// the view's half extents as the film's, a pinhole aperture and aperture.w = 1.
WP_FN ThinLens makeOrthographicLens(vec3 position, vec3 forward, vec3 up, vec2 halfExtent) {
  ThinLens lens = makeThinLens(position, forward, up, halfExtent, 1.0f, WP_FLT_MAX, WP_FLT_MAX);
  lens.aperture = make_vec4(0.0f, 0.0f, 0.0f, 1.0f);
  return lens;
}

WP_FN bool isOrthographic(ThinLens lens) { return lens.aperture.w != 0.0f; }

// The same lens with a regular polygonal aperture of `blades` (>= 3) straight blades,
// inscribed in the circle of the round aperture, its first corner `rotation` radians from
// the image's x axis towards its y axis. Out-of-focus highlights take its shape.
WP_FN ThinLens withBladedAperture(ThinLens lens, uint blades, float rotation) {
  lens.aperture.y = toFloat(blades);
  lens.aperture.z = rotation;
  return lens;
}

// A point uniform over the area of the regular polygon with `sides` (>= 3) corners on the
// unit circle, the first at angle `rotation`: u.x picks one of the equal triangles fanned
// from the centre (its remainder is reused, still uniform), then a uniform point in it.
WP_FN vec2 sampleRegularPolygon(vec2 u, uint sides, float rotation) {
  float scaled = u.x * toFloat(sides);
  uint k = min(toUint(scaled), sides - 1u);
  float wedge = 2.0f * WP_PI / toFloat(sides);
  float a0 = rotation + wedge * toFloat(k);
  float a1 = a0 + wedge;
  vec2 b = sampleUniformTriangle(make_vec2(scaled - toFloat(k), u.y));
  return make_vec2(WP_WARP_COS(a0), WP_WARP_SIN(a0)) * b.x + make_vec2(WP_WARP_COS(a1), WP_WARP_SIN(a1)) * b.y;
}

// A point uniform over the lens's aperture, in scene units along (right, up) from its centre;
// the centre for a pinhole (radius 0), without the disk's sine and cosine (the same branch
// for every ray of a camera; PoCL's generate spent a fifth of its time on them).
WP_FN_INLINED vec2 sampleAperture(ThinLens lens, vec2 u) {
  if (lens.aperture.x == 0.0f) {
    return make_vec2(0.0f, 0.0f);
  }
  uint blades = toUint(lens.aperture.y);
  vec2 p = blades >= 3u ? sampleRegularPolygon(u, blades, lens.aperture.z) : sampleConcentricDisk(u);
  return p * lens.aperture.x;
}

// The primary ray through film position `film` (pixels of a width x height image, y down the
// image) that leaves the aperture at `lensOffset` (scene units along right and up; see
// sampleAperture). Every ray of a film point meets at the point the thin lens focuses it to:
// on the chief ray through the lens centre, at focus distance D along the axis. The chief ray
// runs from the film point, at imageDistance V behind the centre, through the centre; the
// focus point is centre + chief * D / V, and scaling the ray towards it by V / D = f / (D - f)
// keeps the arithmetic finite for a very distant focus.
WP_FN CameraRay thinLensRay(ThinLens lens, vec2 film, uint width, uint height, vec2 lensOffset) {
  vec3 position = make_vec3(lens.position.x, lens.position.y, lens.position.z);
  vec3 right = make_vec3(lens.right.x, lens.right.y, lens.right.z);
  vec3 up = make_vec3(lens.up.x, lens.up.y, lens.up.z);
  vec3 forward = make_vec3(lens.forward.x, lens.forward.y, lens.forward.z);
  float f = lens.position.w;
  float d = lens.forward.w;
  float ndcX = 2.0f * film.x / toFloat(width) - 1.0f;
  float ndcY = 1.0f - 2.0f * film.y / toFloat(height);
  CameraRay ray;
  if (isOrthographic(lens)) {
    ray.origin = position + right * (ndcX * lens.right.w) + up * (ndcY * lens.up.w);
    ray.direction = forward;
    return ray;
  }
  vec3 chief = forward * imageDistance(f, d) + right * (ndcX * lens.right.w) + up * (ndcY * lens.up.w);
  vec3 offset = right * lensOffset.x + up * lensOffset.y;
  ray.origin = position + offset;
  ray.direction = normalize(chief - offset * (f / (d - f)));
  return ray;
}

// The depth of the point a camera ray in `direction` reaches after distance t: how far it
// lies along the optical axis from the lens plane, where every camera ray starts (the
// camera-space Z of the depth pass; a plane facing the camera has one depth everywhere).
WP_FN float cameraDepth(ThinLens lens, vec3 direction, float t) {
  return t * dot(direction, make_vec3(lens.forward.x, lens.forward.y, lens.forward.z));
}

// thinLensRay from a uniformly sampled point of the aperture.
WP_FN_INLINED CameraRay sampleThinLensRay(ThinLens lens, vec2 film, uint width, uint height, vec2 u) {
  return thinLensRay(lens, film, width, height, sampleAperture(lens, u));
}

WP_END

#endif
