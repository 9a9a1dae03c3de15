// Loads one of the project's assets (assets/) as the renderer does, for tests that render
// through the library rather than the executable.
#pragma once

#include "scene/gltf_loader.h"
#include "support/run_wavepath.h"

namespace wp::test {

inline Scene assetScene(const char* name) { return loadScene(sourceDirectory() / "assets" / name); }

}  // namespace wp::test
