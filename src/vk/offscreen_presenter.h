#pragma once
// Frames with no window (`hipr view --headless`): the viewer's frame image is the output, read by
// screenshots and --frames-dir as in a window. Rendering alone paces the frames (no vsync, no
// compositor), so frame rates measured here are what the device allows.
#include "vk/frame_commands.h"
#include "vk/presenter.h"

namespace hipr::vk {

class OffscreenPresenter final : public Presenter {
 public:
  OffscreenPresenter(const Context& ctx, VkExtent2D extent) : m_commands(ctx), m_extent(extent) {}

  VkExtent2D extent() const override { return m_extent; }
  uint32_t min_image_count() const override { return 2; }  // the UI library's least
  uint32_t image_count() const override { return 2; }
  std::string description() const override { return "off-screen (headless)"; }

  void recreate(VkExtent2D extent) override;
  std::optional<PresentFrame> begin_frame() override { return PresentFrame{m_commands.begin(), 0}; }
  bool present(const PresentFrame& frame, const Image& image) override;
  void wait_idle() const override { m_commands.wait(); }

 private:
  FrameCommands m_commands;
  VkExtent2D m_extent;
};

}  // namespace hipr::vk
