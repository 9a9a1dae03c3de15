/* Instantiates the volk Vulkan meta-loader from Debian's libvulkan-volk-dev. */
#include <volk.c>
