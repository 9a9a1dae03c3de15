// Primary rays of the pinhole camera (the thin lens arrives with the camera work).
#ifndef WP_CAMERA_H
#define WP_CAMERA_H

#include "portable.h"

WP_BEGIN

// Unit direction through film position (fx, fy) in pixels, y pointing down the image.
// `right` and `up` are the image-plane axes scaled to the half extents at unit distance.
WP_FN vec3 cameraRayDirection(vec3 forward, vec3 right, vec3 up, vec2 film, uint width, uint height) {
  float ndcX = 2.0f * film.x / toFloat(width) - 1.0f;
  float ndcY = 1.0f - 2.0f * film.y / toFloat(height);
  return normalize(forward + right * ndcX + up * ndcY);
}

WP_END

#endif
