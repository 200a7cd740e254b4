#pragma once
// Dear ImGui on the viewer's window and Vulkan device: the GLFW platform backend (which also
// feeds mouse and keyboard into ImGui's IO, where the viewport reads them) and the Vulkan
// renderer backend drawing into the UI pass.
#include <vulkan/vulkan.h>

#include "app/viewer/window.h"
#include "vk/context.h"
#include "vk/swapchain.h"
#include "vk/ui_pass.h"

namespace hipr::viewer {

class UiLayer {
 public:
  UiLayer(const Window& window, const vk::Context& ctx, const vk::UiPass& pass, const vk::Swapchain& swapchain);
  ~UiLayer();
  UiLayer(const UiLayer&) = delete;
  UiLayer& operator=(const UiLayer&) = delete;

  void new_frame();
  // Ends the ImGui frame and records its draw commands (inside the UI pass).
  void render(VkCommandBuffer cmd);
  void set_min_image_count(uint32_t count);
};

}  // namespace hipr::viewer
