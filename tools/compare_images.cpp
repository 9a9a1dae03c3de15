// wavepath-compare: compares a render (EXR) with a reference EXR. Prints both mean
// radiances, the relative RMSE, and, when the render carries a variance AOV, the per-pixel
// z statistics. A reference of an integer multiple of the render's size is box-averaged
// down first: averaging box-filtered pixels gives exactly the box-filtered larger pixel.
// `wavepath-compare --downsample IN.exr SIZE OUT.exr` writes that box-averaged image (a
// reference small enough to commit, for the tests).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "image/image_io.h"

namespace {

wp::RadianceImage downsample(const wp::RadianceImage& image, uint32_t width, uint32_t height) {
  if (image.width == width && image.height == height) {
    return image;
  }
  if (image.width % width != 0 || image.height % height != 0 || image.width / width != image.height / height) {
    throw std::runtime_error("the reference's size is not an integer multiple of the render's");
  }
  uint32_t f = image.width / width;
  wp::RadianceImage out;
  out.width = width;
  out.height = height;
  out.mean.assign(size_t(width) * height, glm::vec3(0.0f));
  for (uint32_t y = 0; y < image.height; ++y) {
    for (uint32_t x = 0; x < image.width; ++x) {
      out.mean[(y / f) * width + x / f] += image.mean[size_t(y) * image.width + x] / float(f * f);
    }
  }
  return out;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc == 5 && std::string(argv[1]) == "--downsample") {
    try {
      wp::RadianceImage image = wp::readExr(argv[2]);
      const uint32_t size = uint32_t(std::atoi(argv[3]));
      wp::writeImage(argv[4], downsample(image, size, uint32_t(uint64_t(size) * image.height / image.width)));
    } catch (const std::exception& e) {
      std::fprintf(stderr, "wavepath-compare: error: %s\n", e.what());
      return 1;
    }
    return 0;
  }
  if (argc < 3) {
    std::fprintf(stderr, "usage: wavepath-compare RENDER.exr REFERENCE.exr [--exclude-above L]\n"
                         "       wavepath-compare --downsample IN.exr WIDTH OUT.exr\n"
                         "  --exclude-above L: leave out pixels whose reference luminance exceeds L (e.g. lights)\n");
    return 2;
  }
  double excludeAbove = INFINITY;
  if (argc == 5 && std::string(argv[3]) == "--exclude-above") {
    excludeAbove = std::atof(argv[4]);
  }
  try {
    wp::RadianceImage render = wp::readExr(argv[1]);
    wp::RadianceImage reference = downsample(wp::readExr(argv[2]), render.width, render.height);
    glm::dvec3 meanRender(0.0), meanReference(0.0), squaredError(0.0), squaredReference(0.0);
    double zSquared = 0.0;
    size_t used = 0, beyond3 = 0;
    for (size_t i = 0; i < render.mean.size(); ++i) {
      glm::dvec3 r(render.mean[i]), ref(reference.mean[i]);
      if (0.2126 * ref.x + 0.7152 * ref.y + 0.0722 * ref.z > excludeAbove) {
        continue;
      }
      ++used;
      meanRender += r;
      meanReference += ref;
      squaredError += (r - ref) * (r - ref);
      squaredReference += ref * ref;
      if (!render.variance.empty()) {
        for (int c = 0; c < 3; ++c) {
          double v = render.variance[i][c];
          if (v > 0.0) {
            double z = (r[c] - ref[c]) / std::sqrt(v);
            zSquared += z * z;
            beyond3 += std::abs(z) > 3.0;
          }
        }
      }
    }
    meanRender /= double(used);
    meanReference /= double(used);
    glm::dvec3 relativeRmse = glm::sqrt(squaredError / squaredReference);
    std::printf("pixels compared: %zu of %zu\n", used, render.mean.size());
    std::printf("mean render:    %.5f %.5f %.5f\n", meanRender.x, meanRender.y, meanRender.z);
    std::printf("mean reference: %.5f %.5f %.5f\n", meanReference.x, meanReference.y, meanReference.z);
    std::printf("mean ratio:     %.4f %.4f %.4f\n", meanRender.x / meanReference.x, meanRender.y / meanReference.y,
                meanRender.z / meanReference.z);
    std::printf("relative RMSE:  %.4f %.4f %.4f\n", relativeRmse.x, relativeRmse.y, relativeRmse.z);
    if (!render.variance.empty()) {
      std::printf("per-pixel z: mean z^2 %.3f (1 if only the render's noise differs), |z| > 3 in %.2f%% "
                  "(0.27%% expected)\n",
                  zSquared / (3.0 * used), 100.0 * beyond3 / (3.0 * used));
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wavepath-compare: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
