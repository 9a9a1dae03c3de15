// Motion blur benchmark: the same 25 mesh instances held still, sliding, and sliding while
// they turn, rendered in turns; prints the median render time and samples/s of each, and
// with --figure writes the turning render as a PNG (or EXR).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "app/backend_factory.h"
#include "bvh/gpu_scene.h"
#include "bvh/instance_baking.h"
#include "image/image_io.h"
#include "render/wavefront.h"

namespace {

enum class Motion { Still, Sliding, Turning };

// A UV sphere of radius 1 with 2 * rings * (2 rings) triangles, wound outwards.
wp::Mesh uvSphere(int rings, uint32_t material) {
  wp::Mesh m;
  int segments = 2 * rings;
  for (int r = 0; r <= rings; ++r) {
    for (int s = 0; s <= segments; ++s) {
      float theta = 3.14159265f * float(r) / float(rings), phi = 6.28318531f * float(s) / float(segments);
      m.positions.push_back(glm::vec3(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi)));
    }
  }
  for (int r = 0; r < rings; ++r) {
    for (int s = 0; s < segments; ++s) {
      uint32_t a = uint32_t(r * (segments + 1) + s), b = a + uint32_t(segments + 1);
      m.indices.insert(m.indices.end(), {a, a + 1, b, a + 1, b + 1, b});
    }
  }
  m.materials.assign(m.indices.size() / 3, material);
  return m;
}

// Squashed spheres in a 5x5 grid on a floor under a sky and a square light.
wp::Scene benchScene(Motion motion) {
  wp::Scene s;
  wp::Material floor, body, lamp;
  floor.bsdf = body.bsdf = lamp.bsdf = wp::Material::Bsdf::Lambert;
  floor.baseColor = glm::vec3(0.7f);
  body.baseColor = glm::vec3(0.3f, 0.5f, 0.8f);
  lamp.baseColor = glm::vec3(0.0f);
  lamp.emission = glm::vec3(8.0f);
  s.materials = {floor, body, lamp};
  s.planes.push_back({glm::vec3(0, 1, 0), 0.0f, 0});
  s.meshes.push_back(uvSphere(16, 1));
  wp::Mesh light;
  light.positions = {{-1, 4, -1}, {1, 4, -1}, {1, 4, 1}, {-1, 4, 1}};
  light.indices = {0, 1, 2, 0, 2, 3};  // facing down
  light.materials = {2, 2};
  s.meshes.push_back(light);
  s.instances.push_back({1, glm::mat4(1.0f)});
  for (int z = 0; z < 5; ++z) {
    for (int x = 0; x < 5; ++x) {
      glm::vec3 at(float(x - 2), 0.35f, float(z - 2));
      glm::mat4 open = glm::scale(glm::translate(glm::mat4(1.0f), at), glm::vec3(0.35f, 0.25f, 0.2f));
      wp::MeshInstance& inst = s.instances.emplace_back(wp::MeshInstance{0, open});
      glm::mat4 slid = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.0f, 0.0f)) * open;
      if (motion == Motion::Sliding) {
        inst.objectToWorldAtClose = slid;
      } else if (motion == Motion::Turning) {
        inst.objectToWorldAtClose = glm::rotate(slid, 1.2f, glm::vec3(0, 1, 0));
      }
    }
  }
  s.sky = wp::makeEnvironmentMap(1, 1, {glm::vec3(0.2f)});
  s.camera.position = glm::vec3(0.0f, 4.0f, 5.5f);
  s.camera.forward = glm::normalize(-s.camera.position);
  s.camera.up = glm::normalize(glm::cross(glm::cross(s.camera.forward, glm::vec3(0, 1, 0)), s.camera.forward));
  s.hasCamera = true;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  wp::BackendChoice choice;
  wp::RenderSettings settings;
  settings.width = settings.height = 256;
  settings.samplesPerPixel = 16;
  int runs = 3;
  std::string figure;
  for (int i = 1; i < argc; ++i) {
    if (!std::strcmp(argv[i], "--backend") && i + 1 < argc) {
      choice.name = argv[++i];
    } else if (!std::strcmp(argv[i], "--size") && i + 1 < argc) {
      settings.width = settings.height = uint32_t(std::max(1, std::atoi(argv[++i])));
    } else if (!std::strcmp(argv[i], "--spp") && i + 1 < argc) {
      settings.samplesPerPixel = uint32_t(std::max(1, std::atoi(argv[++i])));
    } else if (!std::strcmp(argv[i], "--runs") && i + 1 < argc) {
      runs = std::max(1, std::atoi(argv[++i]));
    } else if (!std::strcmp(argv[i], "--figure") && i + 1 < argc) {
      figure = argv[++i];
    } else {
      std::fprintf(stderr,
                   "usage: wavepath-bench-motion [--backend vulkan|opencl] [--size N] [--spp N] [--runs N] "
                   "[--figure FILE.png]\n");
      return 2;
    }
  }
  try {
    std::unique_ptr<wp::Backend> backend = wp::createBackend(choice);
    const char* names[] = {"still", "sliding", "sliding and turning"};
    std::vector<double> seconds[3];
    wp::RadianceImage turning;
    {
      // Untimed: drivers may compile the pipelines at their first dispatch.
      wp::Scene scene = benchScene(Motion::Turning);
      wp::RenderSettings once = settings;
      once.samplesPerPixel = 1;
      wp::WavefrontRenderer(*backend, scene, wp::packScene(scene), once).render(nullptr);
    }
    // In turns, so that load from elsewhere on a shared machine spreads over all three.
    for (int run = 0; run < runs; ++run) {
      for (int m = 0; m < 3; ++m) {
        wp::Scene scene = benchScene(Motion(m));
        wp::WavefrontRenderer renderer(*backend, scene, wp::packScene(wp::bakeSingleUseMeshes(scene)), settings);
        seconds[m].push_back(renderer.render(nullptr).seconds);
        if (m == 2 && run == 0) {
          turning = renderer.image();
        }
      }
    }
    std::printf("%ux%u, %u spp, 25 instances of a %zu-triangle mesh, median of %d runs on %s\n", settings.width,
                settings.height, settings.samplesPerPixel, benchScene(Motion::Still).meshes[0].triangleCount(), runs,
                backend->deviceName().c_str());
    double samples = double(settings.width) * settings.height * settings.samplesPerPixel;
    for (int m = 0; m < 3; ++m) {
      std::sort(seconds[m].begin(), seconds[m].end());
      double median = seconds[m][seconds[m].size() / 2];
      std::printf("%-20s %7.2f s  %6.3f M samples/s\n", names[m], median, samples / median * 1e-6);
    }
    if (!figure.empty()) {
      wp::writeImage(figure, turning);
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wavepath-bench-motion: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
