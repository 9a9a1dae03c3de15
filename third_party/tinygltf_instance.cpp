// Instantiates tinygltf from Debian's libtinygltf-dev, reading images with stb as Debian
// builds it (sanitizer build only; stb itself comes from stb_instance.c).
#define TINYGLTF_IMPLEMENTATION
#include <tiny_gltf.h>
