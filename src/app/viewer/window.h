#pragma once
// The viewer's GLFW window: creation (no OpenGL context; Vulkan draws), what Vulkan needs to
// present into it (instance extensions, a surface), its size and its event loop. Input is read
// through the UI library's state (ui_layer), which hooks the window's callbacks.
#include <vulkan/vulkan.h>

#include <string>
#include <vector>

struct GLFWwindow;

namespace hipr::viewer {

class Window {
 public:
  // Throws InternalError when no window can be opened (no display: run under xvfb-run).
  Window(const std::string& title, uint32_t width, uint32_t height);
  ~Window();
  Window(const Window&) = delete;
  Window& operator=(const Window&) = delete;

  GLFWwindow* handle() const { return m_window; }
  std::vector<std::string> required_instance_extensions() const;
  VkSurfaceKHR create_surface(VkInstance instance) const;
  // Drawable size in pixels (0 x 0 while minimized).
  VkExtent2D framebuffer_size() const;
  // Framebuffer pixels per window coordinate (cursor positions are in window coordinates).
  float pixel_ratio() const;

  bool should_close() const;
  void poll_events() const;
  // Sleeps until an event arrives or `seconds` pass (nothing to render).
  void wait_events(double seconds) const;
  void set_title(const std::string& title) const;

 private:
  GLFWwindow* m_window = nullptr;
};

}  // namespace hipr::viewer
