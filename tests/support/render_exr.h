// Renders a scene through the wavepath executable into an EXR and reads it back, failing the
// calling test on a non-zero exit or a validation message.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "image/image_io.h"
#include "support/run_wavepath.h"

namespace wp::test {

inline RadianceImage renderExr(const std::string& backend, const std::filesystem::path& scene,
                               const std::vector<std::string>& flags) {
  std::filesystem::path out = scratchDirectory("render-" + scene.stem().string()) / "image.exr";
  std::vector<std::string> args = {"render", scene.string(), "-o", out.string(), "--backend", backend};
  args.insert(args.end(), flags.begin(), flags.end());
  RunResult r = runWavepath(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(r.err.find("validation"), std::string::npos) << r.err;
  return readExr(out);
}

}  // namespace wp::test
