// wavepath-make-samples DIR: writes the glTF sample files (one feature each) into DIR.
#include <cstdio>
#include <exception>

#include "samples/gltf_samples.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: wavepath-make-samples DIR\n");
    return 2;
  }
  try {
    wp::samples::writeAllSamples(argv[1]);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "wavepath-make-samples: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
