// GLFW set-up with errors that name the cause and the headless alternative.
#include "app/viewer/window.h"

#include <algorithm>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include "core/error.h"

namespace wp {
namespace {

std::string gLastGlfwError;

void onGlfwError(int, const char* description) { gLastGlfwError = description; }

}  // namespace

void failNoWindow(const std::string& reason) {
  throw Error("cannot open a window: " + reason + "; run 'wavepath render' to render without a window");
}

void requireWindowSystem() {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    failNoWindow("no window system (" + gLastGlfwError + "; is DISPLAY set?)");
  }
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    failNoWindow("GLFW found no Vulkan loader that can present");
  }
}

Window::Window(uint32_t width, uint32_t height, const std::string& title) {
  requireWindowSystem();
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
  // Hidden until show(): the renderer compiles and uploads for seconds after this, and a
  // mapped window that answers no input meanwhile would take keys it then gets all at once.
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  handle = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (handle == nullptr) {
    std::string reason = gLastGlfwError;
    glfwTerminate();
    failNoWindow("the window system refused a window (" + reason + ")");
  }
}

Window::~Window() {
  glfwDestroyWindow(handle);
  glfwTerminate();
}

void Window::show() { glfwShowWindow(handle); }

void Window::framebufferSize(uint32_t& width, uint32_t& height) const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(handle, &w, &h);
  width = uint32_t(std::max(w, 0));
  height = uint32_t(std::max(h, 0));
}

}  // namespace wp
