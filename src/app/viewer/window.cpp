#include "app/viewer/window.h"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <utility>

#include "core/error.h"
#include "vk/check.h"

namespace hipr::viewer {
namespace {

// GLFW reports errors through a callback; keep the last one for the exception's text.
std::string g_last_error;

void on_glfw_error(int, const char* description) {
  g_last_error = description ? description : "unknown GLFW error";
}

}  // namespace

Window::Window(const std::string& title, uint32_t width, uint32_t height) {
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit())
    throw InternalError("cannot open a window (" + g_last_error +
                        "); without a display, run under xvfb-run or use --headless");
  if (!glfwVulkanSupported()) {
    glfwTerminate();
    throw InternalError("the window system offers no Vulkan presentation (GLFW: no Vulkan loader)");
  }
  glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
  m_window = glfwCreateWindow(int(width), int(height), title.c_str(), nullptr, nullptr);
  if (!m_window) {
    glfwTerminate();
    throw InternalError("cannot create a window: " + g_last_error);
  }
  glfwSetWindowUserPointer(m_window, this);
  glfwSetKeyCallback(m_window, on_key);  // installed first: the UI library chains to it
  glfwSetDropCallback(m_window, on_drop);
}

Window::Window(Headless, uint32_t width, uint32_t height) : m_headless_size{width, height} {}

void Window::on_key(GLFWwindow* window, int key, int, int action, int mods) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (!self || (action != GLFW_PRESS && action != GLFW_REPEAT)) return;
  self->m_keys.push_back({key, (mods & GLFW_MOD_CONTROL) != 0, (mods & GLFW_MOD_SHIFT) != 0,
                          (mods & GLFW_MOD_ALT) != 0, action == GLFW_REPEAT});
}

std::vector<KeyPress> Window::take_key_presses() { return std::exchange(m_keys, {}); }

void Window::on_drop(GLFWwindow* window, int count, const char** paths) {
  auto* self = static_cast<Window*>(glfwGetWindowUserPointer(window));
  if (!self || count <= 0) return;
  Drop drop;
  for (int i = 0; i < count; ++i) drop.paths.emplace_back(paths[i]);
  drop.shift = glfwGetKey(window, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
               glfwGetKey(window, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
  self->m_drops.push_back(std::move(drop));
}

std::vector<Window::Drop> Window::take_drops() { return std::exchange(m_drops, {}); }

Window::~Window() {
  if (headless()) return;
  glfwDestroyWindow(m_window);
  glfwTerminate();
}

std::vector<std::string> Window::required_instance_extensions() const {
  if (headless()) return {};
  uint32_t count = 0;
  const char** names = glfwGetRequiredInstanceExtensions(&count);
  if (!names)
    throw InternalError("the window system needs Vulkan extensions this loader lacks: " +
                        g_last_error);
  return std::vector<std::string>(names, names + count);
}

VkSurfaceKHR Window::create_surface(VkInstance instance) const {
  if (headless()) throw InternalError("a headless viewer has no window surface");
  VkSurfaceKHR surface = VK_NULL_HANDLE;
  VK_CHECK(glfwCreateWindowSurface(instance, m_window, nullptr, &surface));
  return surface;
}

VkExtent2D Window::framebuffer_size() const {
  if (headless()) return m_headless_size;
  int w = 0, h = 0;
  glfwGetFramebufferSize(m_window, &w, &h);
  return {uint32_t(std::max(w, 0)), uint32_t(std::max(h, 0))};
}

float Window::pixel_ratio() const {
  if (headless()) return 1.0f;
  int w = 0, h = 0, fw = 0, fh = 0;
  glfwGetWindowSize(m_window, &w, &h);
  glfwGetFramebufferSize(m_window, &fw, &fh);
  return w > 0 ? float(fw) / float(w) : 1.0f;
}

// Headless, nothing closes the viewer but --exit-after-frames, and no event is awaited: the
// frames run back to back.
bool Window::should_close() const { return !headless() && glfwWindowShouldClose(m_window); }
void Window::poll_events() const {
  if (!headless()) glfwPollEvents();
}
void Window::wait_events(double seconds) const {
  if (!headless()) glfwWaitEventsTimeout(seconds);
}
void Window::set_title(const std::string& title) const {
  if (!headless()) glfwSetWindowTitle(m_window, title.c_str());
}

}  // namespace hipr::viewer
