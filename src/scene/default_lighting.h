// What lights a scene whose user named no sky: the rule, and the note that explains it.
#pragma once

#include <string>

#include "scene/scene.h"

namespace wp {

// The radiance of the default white sky. An emitter brighter than it lights a scene the way
// a lamp does; one at most as bright only glows (glTF's emission without
// KHR_materials_emissive_strength cannot exceed it).
inline constexpr float kDefaultSkyRadiance = 1.0f;

struct DefaultLighting {
  bool whiteSky = false;  // light the scene with a constant sky of kDefaultSkyRadiance
  std::string note;       // one line for the user: what lights the scene, why, which flag changes it
};

// The rule: a scene is lit by its own lights when it has punctual lights (KHR_lights_punctual)
// or emitters brighter than the white sky (emitted luminance, factor times strength, above
// kDefaultSkyRadiance, on a triangle with area, a sphere or a plane); otherwise the white sky
// lights it too, so that no file renders black for want of a light. `file` names it in the note.
DefaultLighting chooseDefaultLighting(const Scene& scene, const std::string& file);

}  // namespace wp
