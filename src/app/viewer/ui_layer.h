#pragma once
// Dear ImGui on the viewer's window and Vulkan device: the GLFW platform backend (which also
// feeds mouse and keyboard into ImGui's IO, where the viewport reads them) and the Vulkan
// renderer backend drawing into the UI pass. Headless there is no platform backend: the UI
// gets the frame's size and time and no input, and draws as in a window.
#include <vulkan/vulkan.h>

#include <vector>

#include "core/timer.h"

#include "app/viewer/window.h"
#include "vk/context.h"
#include "vk/presenter.h"
#include "vk/ui_pass.h"

namespace hipr::viewer {

class UiLayer {
 public:
  UiLayer(const Window& window, const vk::Context& ctx, const vk::UiPass& pass,
          const vk::Presenter& presenter);
  ~UiLayer();
  UiLayer(const UiLayer&) = delete;
  UiLayer& operator=(const UiLayer&) = delete;

  // `presses`: the key presses since the last frame (Window::take_key_presses). A key tapped
  // and released between two frames is shown to the UI as held for this frame: the UI library
  // of Debian 12 (1.86) samples key state once per frame, and would miss such taps (Enter in a
  // text field) at lavapipe's frame rates.
  void new_frame(const std::vector<KeyPress>& presses);
  // Ends the ImGui frame and records its draw commands (inside the UI pass).
  void render(VkCommandBuffer cmd);
  void set_min_image_count(uint32_t count);

 private:
  const Window& m_window;
  Timer m_frame_timer;        // headless: the UI's frame time
  std::vector<int> m_forced;  // keys held down artificially during the last frame
};

}  // namespace hipr::viewer
