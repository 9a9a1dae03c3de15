// glTF animation data (samplers and channels) and its sampling at a time, per glTF 2.0 Appendix C.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

namespace wp {

enum class Interpolation { Step, Linear, CubicSpline };

// Keyframes: strictly increasing times (seconds) and, per keyframe, `width` floats
// (3 for translation and scale, 4 for a rotation quaternion x, y, z, w, the morph target
// count for weights); CUBICSPLINE stores in-tangent, value, out-tangent per keyframe.
struct AnimationSampler {
  std::vector<float> input;
  std::vector<float> output;
  size_t width = 0;
  Interpolation interpolation = Interpolation::Linear;
};

enum class AnimationPath { Translation, Rotation, Scale, Weights };

struct AnimationChannel {
  uint32_t sampler = 0;  // index into the animation's samplers
  uint32_t node = 0;     // glTF node index
  AnimationPath path = AnimationPath::Translation;
};

struct Animation {
  std::string name;
  std::vector<AnimationSampler> samplers;
  std::vector<AnimationChannel> channels;
};

// The sampler's value at `seconds` as `width` floats: STEP holds the previous keyframe,
// LINEAR interpolates linearly, CUBICSPLINE evaluates the Hermite spline with the tangents
// scaled by the keyframe interval. Before the first or after the last keyframe the value is
// clamped to that keyframe. Requires a sampler the loader validated (input not empty and
// strictly increasing, output sized for the interpolation).
std::vector<float> sampleValues(const AnimationSampler& sampler, double seconds);

// The sampler's rotation at `seconds`, a unit quaternion: LINEAR is a spherical linear
// interpolation along the shorter arc, CUBICSPLINE is normalised after the spline.
glm::dquat sampleRotation(const AnimationSampler& sampler, double seconds);

// The last keyframe time over all samplers of the animations (0 without any).
double animationDuration(const std::vector<Animation>& animations);

}  // namespace wp
