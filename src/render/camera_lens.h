// Turns the scene's camera into the thin lens the GPU traces primary rays through.
#pragma once

#include <cstdint>

#include "shaders/common/thin_lens.h"

namespace wp {

struct Camera;
struct GpuScene;

// The lens of `camera` for a width x height image. The glTF vertical field of view holds
// exactly at the focus distance: a pinhole is focused at infinity, and with an aperture the
// focal length is chosen so the film at the thin-lens image distance sees yfov (unless the
// camera sets a focal length, which then decides the view on its sensor).
// Requires camera.optics.focusDistance > 0 when camera.optics.fNumber > 0.
gpu::ThinLens makeLens(const Camera& camera, uint32_t width, uint32_t height);

// Distance along the view axis to what the centre of the image sees (moving instances where
// they are at shutter open), for autofocus; 10 m when the centre ray leaves the scene.
float autofocusDistance(const Camera& camera, const GpuScene& scene);

}  // namespace wp
