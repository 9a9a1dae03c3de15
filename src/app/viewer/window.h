// The viewer's GLFW window: opening it, and the one error that sends users to `wavepath render`.
#pragma once

#include <cstdint>
#include <string>

struct GLFWwindow;

namespace wp {

// Initialises GLFW and opens a resizable window for Vulkan (no OpenGL context) of the given
// size in pixels, hidden until show(). Throws wp::Error, pointing to `wavepath render`, when there is no window
// system (no DISPLAY), or GLFW finds no Vulkan loader able to present.
// Throws wp::Error (pointing to `wavepath render`) unless a window system and a Vulkan
// loader that can present to it are there; leaves GLFW initialised. Cheap: the viewer calls it
// before loading the scene, so a missing display is the only thing the user hears.
void requireWindowSystem();

class Window {
public:
  Window(uint32_t width, uint32_t height, const std::string& title);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  // Maps the window (it opens hidden), once the viewer is ready to draw and take input.
  void show();

  // The framebuffer's size in pixels (0 x 0 while minimised).
  void framebufferSize(uint32_t& width, uint32_t& height) const;

  GLFWwindow* handle = nullptr;
};

// Throws the viewer's "cannot show a window" error with `reason`.
[[noreturn]] void failNoWindow(const std::string& reason);

}  // namespace wp
