/* Instantiates stb_image and stb_image_write from Debian's libstb-dev (sanitizer build only). */
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
