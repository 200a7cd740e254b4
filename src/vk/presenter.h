#pragma once
// Where the viewer's frames go: a window's swapchain (vk/swapchain.h) or nowhere but the
// viewer's own frame image (vk/offscreen_presenter.h: `hipr view --headless`, for machines with
// a GPU and no display). One frame in flight: the path tracer's submissions wait for the GPU
// anyway. A frame is one command buffer: the viewer records its display pass and UI into its
// frame image, then present() records the image's way out, submits and presents.
#include <vulkan/vulkan.h>

#include <optional>
#include <string>

#include "vk/image.h"

namespace hipr::vk {

struct PresentFrame {
  VkCommandBuffer cmd = VK_NULL_HANDLE;  // begun, one-time submit
  uint32_t image_index = 0;              // the swapchain image this frame goes to
};

class Presenter {
 public:
  virtual ~Presenter() = default;

  virtual VkExtent2D extent() const = 0;
  // What the UI library sizes its per-frame buffers by.
  virtual uint32_t min_image_count() const = 0;
  virtual uint32_t image_count() const = 0;
  // One line for the log: how frames are shown.
  virtual std::string description() const = 0;

  // After a window resize, or when begin_frame/present reported the output out of date.
  virtual void recreate(VkExtent2D extent) = 0;
  // Waits for the previous frame and begins this one's command buffer. nullopt: the output no
  // longer matches the window (recreate it and skip this frame).
  virtual std::optional<PresentFrame> begin_frame() = 0;
  // Records the way out of `image` (TRANSFER_SRC_OPTIMAL), then submits and presents the frame.
  // false: the output is out of date or suboptimal (recreate).
  virtual bool present(const PresentFrame& frame, const Image& image) = 0;
  // Waits until the last submitted frame finished on the GPU (before touching what it reads).
  virtual void wait_idle() const = 0;
};

}  // namespace hipr::vk
