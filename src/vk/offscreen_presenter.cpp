#include "vk/offscreen_presenter.h"

namespace hipr::vk {

void OffscreenPresenter::recreate(VkExtent2D extent) {
  m_commands.wait();
  m_extent = extent;
}

bool OffscreenPresenter::present(const PresentFrame&, const Image&) {
  // The frame image is the output: it stays where the UI pass left it, for the next read-back.
  m_commands.submit(VkSubmitInfo{VK_STRUCTURE_TYPE_SUBMIT_INFO});
  return true;
}

}  // namespace hipr::vk
