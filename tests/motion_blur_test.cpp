// Motion blur end to end on both backends (Vulkan under the validation layer): a render of
// moving objects equals the average of renders of the objects held still at many instants.
// The scene is built in memory (glTF has no motion without animation) and rendered in
// process through the same backends and orchestration as the wavepath command.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include <glm/gtc/matrix_transform.hpp>

#include "app/backend_factory.h"
#include "bvh/gpu_scene.h"
#include "bvh/instance_baking.h"
#include "bvh/instance_motion.h"
#include "render/wavefront.h"
#include "support/image_stats.h"

namespace wp::test {
namespace {

glm::mat4 trs(glm::vec3 t, float degrees, glm::vec3 axis, glm::vec3 s) {
  return glm::scale(glm::rotate(glm::translate(glm::mat4(1.0f), t), glm::radians(degrees), glm::normalize(axis)), s);
}

Mesh cube(float half, uint32_t material) {
  Mesh m;
  for (int i = 0; i < 8; ++i) {
    m.positions.push_back(glm::vec3(i & 1 ? half : -half, i & 2 ? half : -half, i & 4 ? half : -half));
  }
  // Counter-clockwise seen from outside: -x, +x, -y, +y, -z, +z.
  m.indices = {0, 4, 6, 0, 6, 2, 1, 3, 7, 1, 7, 5, 0, 1, 5, 0, 5, 4, 2, 6, 7, 2, 7, 3, 0, 2, 3, 0, 3, 1, 4, 5, 7, 4, 7, 6};
  m.materials.assign(12, material);
  return m;
}

// A square in the xz plane facing -y.
Mesh square(float half, uint32_t material) {
  Mesh m;
  m.positions = {{-half, 0, -half}, {half, 0, -half}, {half, 0, half}, {-half, 0, half}};
  m.indices = {0, 1, 2, 0, 2, 3};
  m.materials.assign(2, material);
  return m;
}

// A floor under a dim sky, a cube that slides and turns, an emissive square that slides and
// tilts above it (lighting the floor: its light must follow it), and a still sphere.
Scene movingScene() {
  Scene s;
  Material floor, box, ball, lamp;
  floor.bsdf = box.bsdf = ball.bsdf = lamp.bsdf = Material::Bsdf::Lambert;
  floor.baseColor = glm::vec3(0.7f);
  box.baseColor = glm::vec3(0.2f, 0.5f, 0.8f);
  ball.baseColor = glm::vec3(0.8f, 0.4f, 0.2f);
  lamp.baseColor = glm::vec3(0.0f);
  lamp.emission = glm::vec3(6.0f, 5.0f, 4.0f);
  lamp.doubleSided = true;
  s.materials = {floor, box, ball, lamp};
  s.planes.push_back({glm::vec3(0, 1, 0), 0.0f, 0});
  s.meshes = {cube(0.25f, 1), square(0.2f, 3)};
  s.instances.push_back({0, trs(glm::vec3(-0.45f, 0.3f, 0.0f), 0.0f, glm::vec3(0, 1, 0), glm::vec3(1.0f))});
  s.instances[0].objectToWorldAtClose = trs(glm::vec3(0.35f, 0.4f, 0.1f), 70.0f, glm::vec3(0.3f, 1, 0.2f),
                                            glm::vec3(1.2f));
  s.instances.push_back({1, trs(glm::vec3(-0.3f, 1.0f, 0.4f), 0.0f, glm::vec3(1, 0, 0), glm::vec3(1.0f))});
  s.instances[1].objectToWorldAtClose = trs(glm::vec3(0.3f, 1.1f, 0.3f), 30.0f, glm::vec3(1, 0, 0), glm::vec3(1.0f));
  s.spheres.push_back({trs(glm::vec3(0.7f, 0.2f, -0.5f), 0.0f, glm::vec3(0, 1, 0), glm::vec3(0.2f)), 2});
  s.sky = makeEnvironmentMap(1, 1, {glm::vec3(0.3f)});
  s.camera.position = glm::vec3(0.0f, 1.2f, 2.4f);
  s.camera.forward = glm::normalize(glm::vec3(0.0f, 0.45f, 0.0f) - s.camera.position);
  s.camera.up = glm::normalize(glm::cross(glm::cross(s.camera.forward, glm::vec3(0, 1, 0)), s.camera.forward));
  s.camera.yfov = 0.8f;
  s.hasCamera = true;
  return s;
}

// The scene with every mover held still where the shutter-time interpolation puts it at u.
Scene posedAt(Scene s, float u) {
  auto pose = [u](glm::mat4& toWorld, std::optional<glm::mat4>& atClose) {
    if (atClose) {
      toWorld = objectToWorldAt(*makeMotionKeys(toWorld, *atClose), u);
      atClose.reset();
    }
  };
  for (MeshInstance& inst : s.instances) pose(inst.objectToWorld, inst.objectToWorldAtClose);
  for (Sphere& sphere : s.spheres) pose(sphere.objectToWorld, sphere.objectToWorldAtClose);
  return s;
}

class MotionBlur : public ::testing::TestWithParam<std::string> {
protected:
  void SetUp() override {
    // The OpenCL program cache of this test run (see tests/CMakeLists.txt).
    setenv("WAVEPATH_CACHE_DIR", WAVEPATH_TEST_CACHE_DIR, 1);
    choice_.name = GetParam();
    choice_.validate = true;
    backend_ = createBackend(choice_);
  }
  void TearDown() override { EXPECT_NO_THROW(checkValidation(choice_)); }

  RadianceImage render(const Scene& scene, uint32_t spp, uint32_t seed) {
    RenderSettings settings;
    settings.width = kSize;
    settings.height = kSize;
    settings.samplesPerPixel = spp;
    settings.maxBounces = 3;
    settings.seed = seed;
    WavefrontRenderer renderer(*backend_, scene, packScene(bakeSingleUseMeshes(scene)), settings);
    renderer.render(nullptr);
    return renderer.image();
  }

  static constexpr uint32_t kSize = 48;
  BackendChoice choice_;
  std::unique_ptr<Backend> backend_;
};

std::string backendName(const ::testing::TestParamInfo<std::string>& info) { return info.param; }

// The mean of `image` over the square region of 12x12 pixels at (rx, ry), with its standard error.
ImageMean regionMean(const RadianceImage& image, int rx, int ry) {
  RadianceImage region;
  for (int y = 12 * ry; y < 12 * ry + 12; ++y) {
    for (int x = 12 * rx; x < 12 * rx + 12; ++x) {
      region.mean.push_back(image.mean[size_t(y) * image.width + x]);
      region.variance.push_back(image.variance[size_t(y) * image.width + x]);
    }
  }
  return imageMean(region);
}

// The largest z over the 16 regions and 3 channels of the difference of two images.
double largestRegionZ(const RadianceImage& a, const RadianceImage& b) {
  double largest = 0.0;
  for (int ry = 0; ry < 4; ++ry) {
    for (int rx = 0; rx < 4; ++rx) {
      ImageMean ma = regionMean(a, rx, ry), mb = regionMean(b, rx, ry);
      for (int c = 0; c < 3; ++c) {
        largest = std::max(largest, meanZ(ma, mb, c));
      }
    }
  }
  return largest;
}

// The mean over pixels and channels of z^2, z = (a - b) / sqrt(var_a + var_b) per pixel.
double meanSquaredPixelZ(const RadianceImage& a, const RadianceImage& b) {
  double sum = 0.0;
  size_t count = 0;
  for (size_t i = 0; i < a.mean.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      double variance = double(a.variance[i][c]) + double(b.variance[i][c]);
      if (variance > 0.0) {
        double difference = double(a.mean[i][c]) - double(b.mean[i][c]);
        sum += difference * difference / variance;
        ++count;
      }
    }
  }
  return sum / double(count);
}

// Motion blur integrates the image over the shutter; the average of K renders at the
// stratified instants (k + 0.5) / K estimates the same integral (weights 1/K, variances
// 1/K^2, seeds apart so the renders are independent). Its quadrature error is small against
// the noise: a pixel that an edge crosses during the shutter sees a step in time, which the
// midpoint rule misses by at most half a stratum, an RMS error of jump / (K sqrt 12) = 0.9%
// of the jump at K = 32, against a noise of about 4% of the jump per pixel at 256 samples;
// averaged over regions it shrinks further. Checks, each a z statistic of the difference
// with standard errors from the variance AOVs:
// - whole image, per channel: z < 4 (two-sided p = 6e-5), with the noise below 1% of the mean;
// - 16 regions of 12x12 pixels, per channel: z < 4.5 (48 comparisons: chance failure 3e-4);
// - per pixel, mean z^2 < 2: 1 for normal z, but pixel variances estimated from few samples
//   of a light that only BSDF sampling finds have heavier tails (1.06 to 1.27 over three
//   seed sets here); an edge of the blur misplaced by a pixel would add far more;
// - the test can fail: the same check between the blurred render and the objects held still
//   at shutter open finds some region far off (z > 10).
TEST_P(MotionBlur, EqualsTheAverageOfRendersAtManyInstants) {
  Scene scene = movingScene();
  RadianceImage blurred = render(scene, 256, 1000);

  const int instants = 32;
  RadianceImage average;
  average.width = average.height = kSize;
  average.mean.assign(size_t(kSize) * kSize, glm::vec3(0.0f));
  average.variance.assign(size_t(kSize) * kSize, glm::vec3(0.0f));
  for (int k = 0; k < instants; ++k) {
    RadianceImage still = render(posedAt(scene, (float(k) + 0.5f) / float(instants)), 256 / instants, uint32_t(k + 1));
    for (size_t i = 0; i < average.mean.size(); ++i) {
      average.mean[i] += still.mean[i] / float(instants);
      average.variance[i] += still.variance[i] / float(instants * instants);
    }
  }

  ImageMean a = imageMean(blurred), b = imageMean(average);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(meanZ(a, b, c), 4.0) << "channel " << c << ": " << a.mean[c] << " vs " << b.mean[c];
    EXPECT_LT(differenceError(a, b, c), 0.01 * a.mean[c]) << "channel " << c;
  }
  EXPECT_LT(largestRegionZ(blurred, average), 4.5);
  EXPECT_LT(meanSquaredPixelZ(blurred, average), 2.0);

  RadianceImage atOpen = render(posedAt(scene, 0.0f), 256, 2000);
  EXPECT_GT(largestRegionZ(blurred, atOpen), 10.0);
}

// Scenes where nothing moves run the stages built without motion blur, which would otherwise
// cost them time (docs/motion-blur.md); the test above checks that moving ones get the motion
// build (with the still one they would render as at shutter open). Switching builds must
// leave every buffer bound to the switched-in kernels: a still render after a moving one
// equals, bit for bit, the same render before it.
TEST_P(MotionBlur, StillScenesRunTheStagesWithoutMotion) {
  Scene moving = movingScene();
  Scene still = posedAt(moving, 0.0f);
  RadianceImage before = render(still, 4, 7);
  EXPECT_FALSE(backend_->motionKernels());
  render(moving, 4, 7);
  EXPECT_TRUE(backend_->motionKernels());
  RadianceImage after = render(still, 4, 7);
  EXPECT_FALSE(backend_->motionKernels());
  EXPECT_TRUE(before.mean == after.mean && before.variance == after.variance);
}

INSTANTIATE_TEST_SUITE_P(Backend, MotionBlur, ::testing::Values(std::string("vulkan"), std::string("opencl")),
                         backendName);

}  // namespace
}  // namespace wp::test
