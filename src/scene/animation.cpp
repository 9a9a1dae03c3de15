// Sampling of glTF animation samplers: STEP, LINEAR (slerp for rotations) and CUBICSPLINE.
#include "scene/animation.h"

#include <algorithm>
#include <cmath>

namespace wp {

namespace {

// Where `seconds` falls: between keyframes `k` and `k + 1` at fraction `u` in [0, 1), or
// clamped to keyframe `k` (u = 0, single = true) outside the input range.
struct Keyframe {
  size_t k = 0;
  double u = 0.0;
  double interval = 0.0;  // t[k + 1] - t[k]
  bool single = true;
};

Keyframe locateTime(const std::vector<float>& input, double seconds) {
  if (!(seconds > input.front())) return {0, 0.0, 0.0, true};
  if (seconds >= input.back()) return {input.size() - 1, 0.0, 0.0, true};
  const size_t k = static_cast<size_t>(std::upper_bound(input.begin(), input.end(), seconds) - input.begin()) - 1;
  const double interval = double(input[k + 1]) - double(input[k]);
  return {k, (seconds - double(input[k])) / interval, interval, false};
}

// Keyframe k's value (CUBICSPLINE keeps it between the two tangents).
const float* valueAt(const AnimationSampler& s, size_t k) {
  const size_t element = s.interpolation == Interpolation::CubicSpline ? 3 * k + 1 : k;
  return s.output.data() + element * s.width;
}

// glTF stores x, y, z, w. A spline may pass through zero, which stands for no rotation
// rather than a NaN.
glm::dquat toQuat(const float* v) {
  const glm::dquat q(v[3], v[0], v[1], v[2]);
  const double length = glm::length(q);
  return length > 0.0 ? q / length : glm::dquat(1.0, 0.0, 0.0, 0.0);
}

// Spherical linear interpolation along the shorter arc; nearly parallel ends fall back to a
// normalised linear blend, where the sine below would lose its precision.
glm::dquat slerpShortest(const glm::dquat& a, glm::dquat b, double u) {
  double cosine = glm::dot(a, b);
  if (cosine < 0.0) {
    b = -b;
    cosine = -cosine;
  }
  if (cosine > 0.9995) return glm::normalize(a * (1.0 - u) + b * u);
  const double angle = std::acos(cosine);
  const double sine = std::sin(angle);
  return glm::normalize(a * (std::sin((1.0 - u) * angle) / sine) + b * (std::sin(u * angle) / sine));
}

}  // namespace

std::vector<float> sampleValues(const AnimationSampler& s, double seconds) {
  const Keyframe f = locateTime(s.input, seconds);
  const float* v0 = valueAt(s, f.k);
  std::vector<float> out(v0, v0 + s.width);
  if (f.single || s.interpolation == Interpolation::Step) return out;
  const float* v1 = valueAt(s, f.k + 1);
  const double u = f.u;
  if (s.interpolation == Interpolation::Linear) {
    for (size_t i = 0; i < s.width; ++i) out[i] = float(double(v0[i]) * (1.0 - u) + double(v1[i]) * u);
    return out;
  }
  // Hermite basis of glTF 2.0 Appendix C; the out-tangent of k and the in-tangent of k + 1
  // are per second, hence the scaling by the interval.
  const float* outTangent0 = v0 + s.width;
  const float* inTangent1 = v1 - s.width;
  const double u2 = u * u;
  const double u3 = u2 * u;
  const double h00 = 2 * u3 - 3 * u2 + 1;
  const double h10 = (u3 - 2 * u2 + u) * f.interval;
  const double h01 = -2 * u3 + 3 * u2;
  const double h11 = (u3 - u2) * f.interval;
  for (size_t i = 0; i < s.width; ++i) {
    out[i] = float(h00 * v0[i] + h10 * outTangent0[i] + h01 * v1[i] + h11 * inTangent1[i]);
  }
  return out;
}

glm::dquat sampleRotation(const AnimationSampler& s, double seconds) {
  if (s.interpolation == Interpolation::Linear) {
    const Keyframe f = locateTime(s.input, seconds);
    const glm::dquat q0 = toQuat(valueAt(s, f.k));
    return f.single ? q0 : slerpShortest(q0, toQuat(valueAt(s, f.k + 1)), f.u);
  }
  return toQuat(sampleValues(s, seconds).data());
}

double animationDuration(const std::vector<Animation>& animations) {
  double duration = 0.0;
  for (const Animation& animation : animations) {
    for (const AnimationSampler& sampler : animation.samplers) {
      duration = std::max(duration, double(sampler.input.back()));
    }
  }
  return duration;
}

}  // namespace wp
