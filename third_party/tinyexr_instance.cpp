// Instantiates tinyexr from Debian's libtinyexr-dev, with zlib as Debian builds it (sanitizer build only).
#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>
