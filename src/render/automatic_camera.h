// A camera for a scene whose file has none: from outside, or from inside an enclosed scene lit
// from within, chosen by casting rays through the packed scene.
#pragma once

#include <string>

#include "bvh/gpu_scene.h"
#include "scene/scene.h"

namespace wp {

// The vertical field of view of a view from inside, in radians (65 degrees): wider than the
// outside view's, as a room is seen from within it.
inline constexpr float kInteriorYfov = 1.1344640f;

struct AutomaticCamera {
  Camera camera;
  bool inside = false;  // the view is from inside an enclosure
  std::string note;     // one line for the user: where it looks from, why, how to choose
};

// Where to look at `scene` (packed as `packed`) from when its file has no camera. From the
// centre of its bounds rays go out in 256 directions; when at least 95% of them hit something
// (the centre is enclosed), the scene has no sky (its own lights light it) and one of those
// lights can be seen from the centre (a room lit from within, not a solid object with lamps
// around it, which its own surface hides from its centre), the camera stands inside: near the
// wall opposite the horizontal direction with the most free space, looking that way.
// Otherwise it is frameScene's view from +z, the front of a glTF asset. `file` names the
// scene in the note.
AutomaticCamera chooseAutomaticCamera(const Scene& scene, const GpuScene& packed, const std::string& file);

}  // namespace wp
