// End-to-end renders of KHR_lights_punctual lamps on both backends: the irradiance each kind
// gives a Lambertian plane against its formula, a lamp moving while the shutter is open,
// MIS, light sampling and BSDF sampling agreeing beside an area light, and the lamps asset.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <algorithm>
#include <functional>
#include <string>

#include <glm/glm.hpp>

#include "image/image_io.h"
#include "support/image_stats.h"
#include "support/run_wavepath.h"

namespace wp::test {
namespace {

using Backends = ::testing::TestWithParam<std::string>;

constexpr double kPi = 3.14159265358979323846;
constexpr double kAlbedo = 0.5;
constexpr int kSize = 24;
constexpr double kHalfView = 2.0;  // the orthographic view covers [-2, 2] x [-2, 2] of the plane

// A Lambertian plane y = 0 of albedo 0.5 seen straight down by an orthographic camera at
// height 5 (image x along +x, image y along +z), lit by the light `light` placed by node
// `lightNode`, and an animation when given.
std::string planeScene(const std::string& light, const std::string& lightNode, const std::string& animation = "") {
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2]}],
  "extensionsUsed": ["KHR_lights_punctual"], "extensionsRequired": ["KHR_lights_punctual"],
  "extensions": {"KHR_lights_punctual": {"lights": [)" + light + R"(]}},
  "nodes": [{"extras": {"wavepath": {"shape": "plane", "material": 0}}},
            {"camera": 0, "translation": [0, 5, 0], "rotation": [-0.70710678, 0, 0, 0.70710678]},
            )" + lightNode + R"(],
  "cameras": [{"type": "orthographic", "orthographic": {"xmag": 2, "ymag": 2, "znear": 0.1, "zfar": 10}}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.5, 0.5, 0.5, 1]},
                 "extras": {"wavepath": {"bsdf": "lambert"}}}])" + animation + "}";
}

// Renders `scene` with direct light only (the plane cannot light itself anyway).
RadianceImage renderPlane(const std::string& name, const std::string& scene, const std::string& backend,
                          const std::vector<std::string>& extra = {}) {
  const std::filesystem::path dir = scratchDirectory("lamp-" + name + "-" + backend);
  std::ofstream(dir / "scene.gltf") << scene;
  std::vector<std::string> args = {"render", (dir / "scene.gltf").string(), "-o", (dir / "out.exr").string(),
                                   "--width", std::to_string(kSize), "--height", std::to_string(kSize), "--spp", "32",
                                   "--max-depth", "0", "--backend", backend};
  args.insert(args.end(), extra.begin(), extra.end());
  const RunResult r = runWavepath(args);
  EXPECT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("is lit by its 1 lamp, so it gets no sky"), std::string::npos) << r.err;
  return readExr(dir / "out.exr");
}

// Each pixel against the mean of `radiance` (a function of the plane point (x, z)) over its
// footprint, by the midpoint rule on 16 x 16 points: the render's only randomness is where in
// the pixel a sample lands, so they agree within its own standard error (5 of them) and float
// rounding, plus 1e-4 of the image's brightest pixel for a pixel that an edge (a spot's cone)
// crosses by a sliver that none of its samples may land in, leaving its variance estimate 0.
void expectPixelsMatch(const RadianceImage& image, const std::function<glm::dvec3(double, double)>& radiance) {
  const double pixel = 2.0 * kHalfView / kSize;
  std::vector<glm::dvec3> expected(size_t(kSize) * kSize, glm::dvec3(0.0));
  double peak = 0.0;
  for (int py = 0; py < kSize; ++py) {
    for (int px = 0; px < kSize; ++px) {
      glm::dvec3& e = expected[size_t(py) * kSize + px];
      for (int a = 0; a < 16; ++a) {
        for (int b = 0; b < 16; ++b) {
          const double x = -kHalfView + (px + (a + 0.5) / 16.0) * pixel;
          const double z = -kHalfView + (py + (b + 0.5) / 16.0) * pixel;
          e += radiance(x, z) / 256.0;
        }
      }
      peak = std::max({peak, e.x, e.y, e.z});
    }
  }
  ASSERT_GT(peak, 0.0);
  for (size_t i = 0; i < expected.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      const double se = std::sqrt(double(image.variance[i][c]));
      ASSERT_NEAR(image.mean[i][c], expected[i][c], 5.0 * se + 1e-4 * expected[i][c] + 1e-4 * peak)
          << "pixel " << i % kSize << "," << i / kSize << " channel " << c;
    }
  }
}

// A point light of colour (1, 0.5, 0.25) and 1366 cd, I = colour * 1366 / 683 W/sr, one unit
// above (0.3, 0, -0.2): radiance a / pi * I cos(theta) / r^2 = a / pi * I h / r^3.
TEST_P(Backends, PointLightGivesIntensityTimesCosineOverDistanceSquared) {
  const RadianceImage image =
      renderPlane("point", planeScene(R"({"type": "point", "color": [1, 0.5, 0.25], "intensity": 1366})",
                                      R"({"translation": [0.3, 1, -0.2], "extensions": {"KHR_lights_punctual": {"light": 0}}})"),
                  GetParam());
  const glm::dvec3 intensity = glm::dvec3(1.0, 0.5, 0.25) * 2.0;
  expectPixelsMatch(image, [&](double x, double z) {
    const double r2 = (x - 0.3) * (x - 0.3) + 1.0 + (z + 0.2) * (z + 0.2);
    return kAlbedo / kPi * intensity * (1.0 / (r2 * std::sqrt(r2)));
  });
}

// A spot 1.5 above the origin pointing down, cones 0.3 and 0.6 rad, 2049 cd: the point
// light's formula times the extension's falloff ((cos - cos_outer) / (cos_inner -
// cos_outer))^2, clamped to [0, 1].
TEST_P(Backends, SpotLightFallsOffAsTheExtensionSays) {
  const RadianceImage image = renderPlane(
      "spot",
      planeScene(R"({"type": "spot", "intensity": 2049, "spot": {"innerConeAngle": 0.3, "outerConeAngle": 0.6}})",
                 R"({"translation": [0, 1.5, 0], "rotation": [-0.70710678, 0, 0, 0.70710678],
                     "extensions": {"KHR_lights_punctual": {"light": 0}}})"),
      GetParam());
  const double cosInner = std::cos(0.3), cosOuter = std::cos(0.6);
  expectPixelsMatch(image, [&](double x, double z) {
    const double h = 1.5, r2 = x * x + h * h + z * z, r = std::sqrt(r2);
    const double t = std::clamp((h / r - cosOuter) / (cosInner - cosOuter), 0.0, 1.0);
    return glm::dvec3(kAlbedo / kPi * 3.0 * t * t * h / (r2 * r));
  });
}

// A sun of 6830 lux (E = 10 W/m^2) whose light travels along (0, -0.866, -0.5): every point
// gets E cos(30 degrees).
TEST_P(Backends, DirectionalLightGivesIrradianceTimesCosine) {
  const RadianceImage image = renderPlane(
      "sun",
      planeScene(R"({"type": "directional", "intensity": 6830})",
                 R"({"rotation": [-0.5, 0, 0, 0.8660254], "extensions": {"KHR_lights_punctual": {"light": 0}}})"),
      GetParam());
  expectPixelsMatch(image, [](double, double) { return glm::dvec3(kAlbedo / kPi * 10.0 * std::sqrt(3.0) / 2.0); });
}

// A point light on an animated node slides from x = -1 to x = 1 in the second after 0 s; with
// the shutter open over that second each pixel sees the time average of the point light's
// formula (the light moves in a straight line, as instances do). The same light frozen at
// shutter open is told apart.
TEST_P(Backends, LampOnAnAnimatedNodeBlursOverTheShutter) {
  const std::string animation = R"(,
  "animations": [{"channels": [{"sampler": 0, "target": {"node": 2, "path": "translation"}}],
                  "samplers": [{"input": 0, "output": 1, "interpolation": "LINEAR"}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 2, "type": "SCALAR", "min": [0], "max": [1]},
                {"bufferView": 1, "componentType": 5126, "count": 2, "type": "VEC3"}],
  "bufferViews": [{"buffer": 0, "byteLength": 8}, {"buffer": 0, "byteOffset": 8, "byteLength": 24}],
  "buffers": [{"byteLength": 32, "uri": "data:application/octet-stream;base64,AAAAAAAAgD8AAIC/AACAPwAAAAAAAIA/AACAPwAAAAA="}])";
  const std::string scene =
      planeScene(R"({"type": "point", "intensity": 683})",
                 R"({"translation": [-1, 1, 0], "extensions": {"KHR_lights_punctual": {"light": 0}}})", animation);
  const RadianceImage blurred = renderPlane("moving", scene, GetParam(), {"--time", "0", "--shutter", "1"});
  const auto average = [](double x, double z) {
    glm::dvec3 sum(0.0);
    for (int k = 0; k < 64; ++k) {
      const double lightX = -1.0 + 2.0 * (k + 0.5) / 64.0;
      const double r2 = (x - lightX) * (x - lightX) + 1.0 + z * z;
      sum += glm::dvec3(kAlbedo / kPi / (r2 * std::sqrt(r2))) / 64.0;
    }
    return sum;
  };
  expectPixelsMatch(blurred, average);
  const RadianceImage frozen = renderPlane("frozen", scene, GetParam(), {"--time", "0"});
  const size_t right = size_t(kSize / 2) * kSize + kSize - 2;  // x = 1.7: the light ends near it
  EXPECT_GT(blurred.mean[right].r, 1.5 * frozen.mean[right].r);
}

// Lamps beside an emissive quad, over a Lambertian floor, a glossy sphere and a metal box:
// MIS, light sampling alone and BSDF sampling alone (which still light-samples the lamps, as
// no BSDF sample can hit them) have the same mean.
TEST_P(Backends, MisLightAndBsdfSamplingAgreeWithLampsAndAnAreaLight) {
  const std::string scene = R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0, 1, 2, 3, 4, 5, 6, 7]}],
  "extensionsUsed": ["KHR_lights_punctual", "KHR_materials_emissive_strength"],
  "extensions": {"KHR_lights_punctual": {"lights": [
    {"type": "point", "color": [1, 0.8, 0.6], "intensity": 300},
    {"type": "spot", "intensity": 800, "spot": {"innerConeAngle": 0.2, "outerConeAngle": 0.5}},
    {"type": "directional", "intensity": 400}]}},
  "nodes": [{"extras": {"wavepath": {"shape": "plane", "material": 0}}},
            {"translation": [0, 0.7, 0], "extras": {"wavepath": {"shape": "sphere", "radius": 0.7, "material": 1}}},
            {"translation": [1.3, 0.4, 0.5], "extras": {"wavepath": {"shape": "sphere", "radius": 0.4, "material": 2}}},
            {"mesh": 0, "translation": [-1.5, 2.5, 0]},
            {"camera": 0, "translation": [0, 2, 6], "rotation": [-0.1305262, 0, 0, 0.9914449]},
            {"translation": [-1, 2, 1], "extensions": {"KHR_lights_punctual": {"light": 0}}},
            {"translation": [1.5, 3, 0], "rotation": [-0.70710678, 0, 0, 0.70710678],
             "extensions": {"KHR_lights_punctual": {"light": 1}}},
            {"rotation": [-0.5, 0, 0, 0.8660254], "extensions": {"KHR_lights_punctual": {"light": 2}}}],
  "cameras": [{"type": "perspective", "perspective": {"yfov": 0.8, "znear": 0.05}}],
  "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1, "material": 3}]}],
  "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3", "min": [-0.5, 0, -0.5], "max": [0.5, 0, 0.5]},
                {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteLength": 48}, {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AAAAvwAAAAAAAAC/AAAAPwAAAAAAAAC/AAAAPwAAAAAAAAA/AAAAvwAAAAAAAAA/AAACAAEAAAADAAIA"}],
  "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.6, 0.6, 0.6, 1], "metallicFactor": 0, "roughnessFactor": 1}},
                {"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.3, 0.2, 1], "metallicFactor": 0, "roughnessFactor": 0.4}},
                {"pbrMetallicRoughness": {"baseColorFactor": [0.9, 0.8, 0.5, 1], "metallicFactor": 1, "roughnessFactor": 0.5}},
                {"emissiveFactor": [1, 1, 1], "extensions": {"KHR_materials_emissive_strength": {"emissiveStrength": 8}},
                 "doubleSided": true}]})";
  const std::filesystem::path dir = scratchDirectory("lamps-agree-" + GetParam());
  std::ofstream(dir / "scene.gltf") << scene;
  std::vector<ImageMean> means;
  const std::vector<std::string> modes = {"mis", "nee", "bsdf"};
  for (const std::string& mode : modes) {
    const std::filesystem::path out = dir / (mode + ".exr");
    const RunResult r = runWavepath({"render", (dir / "scene.gltf").string(), "-o", out.string(), "--width", "48",
                                     "--height", "32", "--spp", "128", "--mode", mode, "--backend", GetParam()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    means.push_back(imageMean(readExr(out)));
  }
  expectAgreement(means, modes);
}

// The asset written by tools/make_lamps_scene.py (a point, a spot and a sun in
// extensionsRequired, as Blender exports lamps) renders without an error or a black image.
TEST_P(Backends, LampsAssetRenders) {
  const std::filesystem::path dir = scratchDirectory("lamps-asset-" + GetParam());
  const RunResult r = runWavepath({"render", (sourceDirectory() / "assets" / "lamps.gltf").string(), "-o",
                                   (dir / "out.exr").string(), "--width", "32", "--spp", "4", "--backend", GetParam()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("is lit by its 3 lamps, so it gets no sky"), std::string::npos) << r.err;
  EXPECT_EQ(r.err.find("almost black"), std::string::npos) << r.err;
  const ImageMean mean = imageMean(readExr(dir / "out.exr"));
  EXPECT_GT(mean.mean.g, 0.05);
}

INSTANTIATE_TEST_SUITE_P(Backend, Backends, ::testing::Values("vulkan", "opencl"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace wp::test
