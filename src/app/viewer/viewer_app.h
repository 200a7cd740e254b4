#pragma once
// The viewer: one window, one device, one editing session (run_viewer makes one and runs it).
// Its frame loop is viewer.cpp; what it reads and writes as files (scenes, screenshots, frames,
// statistics) is viewer_output.cpp.
#include <vulkan/vulkan.h>

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "app/viewer/panels.h"
#include "app/viewer/session.h"
#include "app/viewer/ui_layer.h"
#include "app/viewer/view_layout.h"
#include "app/viewer/viewer.h"
#include "app/viewer/viewer_state.h"
#include "app/viewer/viewport_input.h"
#include "app/viewer/window.h"
#include "core/timer.h"
#include "render/display_pass.h"
#include "vk/context.h"
#include "vk/image.h"
#include "vk/presenter.h"
#include "vk/ui_pass.h"

namespace hipr::viewer {

// With panels, the window is at least this tall so the side panel has room.
constexpr uint32_t kMinUiHeight = 640;
// The frame image: what the display pass writes, the UI draws on and screenshots read.
constexpr VkFormat kFrameFormat = VK_FORMAT_R8G8B8A8_UNORM;
constexpr VkImageUsageFlags kFrameUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT |
                                          VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
                                          VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;

class Viewer {
 public:
  // The last frame may still be reading the buffers and images destroyed with the members
  // (when an exception ends the loop early).
  ~Viewer() { vkDeviceWaitIdle(m_ctx.device()); }
  Viewer(const ViewerOptions& options, Scene scene);

  int run();

 private:
  static uint32_t window_width(const ViewerOptions& o) {
    return o.common.render.width + (o.show_ui ? uint32_t(kPanelWidth) : 0u);
  }
  static uint32_t window_height(const ViewerOptions& o) {
    return o.show_ui ? std::max(o.common.render.height, kMinUiHeight) : o.common.render.height;
  }

  void resize(VkExtent2D extent);
  void show_message(const std::string& text);
  void show_message_frame(const std::string& text);
  void run_script(uint32_t frame);
  void draw_ui(const ViewLayout& layout, const std::vector<KeyPress>& keys);
  void handle_requests();
  // Applies a pending viewer setting once; a failure becomes a message, the session unchanged.
  template <class T, class Apply>
  void take_setting_request(std::optional<T>& request, const char* what, Apply apply);
  void render_steps();
  // Auto exposure: meters the displayed radiance on the first frames, then every 8th.
  void meter_exposure(uint32_t frame_index);
  void update_overlay();
  void update_source(VkCommandBuffer cmd);
  bool present(const ViewLayout& layout);
  bool draw_and_present(const vk::PresentFrame& frame, const DisplayView& view);
  ViewLayout layout() const;
  void write_stats(double seconds) const;
  nlohmann::json rendering_stats() const;
  void dump_frame(uint32_t frame_index, double frame_seconds);
  void write_frame_log() const;
  void open_scene();
  void save_scene_file();
  void take_screenshot(const std::filesystem::path& path);

  Timer m_started;  // first member: times the whole start (window, device, kernels)
  double m_first_frame_seconds = -1.0;
  const ViewerOptions& m_options;
  Window m_window;
  vk::Context m_ctx;
  std::unique_ptr<vk::Presenter> m_presenter;  // the window's swapchain, or off screen
  vk::UiPass m_ui_pass;
  vk::Image m_frame;
  UiLayer m_ui;
  DisplayPass m_display;
  std::unique_ptr<Session> m_session;
  ViewerState m_state;
  ViewportInput m_input;
  size_t m_script_next = 0;
  nlohmann::json m_frame_log =
      nlohmann::json::array();  // --frames-dir: what each dumped frame shows
  uint64_t m_frames = 0;
  uint64_t m_steps = 0;
  // What the display pass reads: the renderer's display, or the denoiser's copy of it (made
  // again whenever the display or the denoiser's settings change).
  struct SourceKey {
    uint64_t renderer = 0;          // Session::renderer_id() (from 1: a new session or settings
                                    // that rebuild the renderer bring another)
    uint64_t version = UINT64_MAX;  // Session::display_version() the copy was made at
    DenoiseSettings denoise;
    bool operator==(const SourceKey&) const = default;
  } m_source_key;
  double m_render_ms = 0.0;          // the last frame's scheduling steps
  double m_frame_overhead_ms = 0.0;  // a frame's other work, smoothed (the adaptive budget)
  // Frames that ran steps: their times (the frame rate while re-rendering) and the bytes copied
  // between host and device during them.
  std::vector<double> m_rendering_frame_ms;
  vk::DeviceCounts m_rendering_counts;  // submissions waited for: the frame's own not counted
  // What the current overlay was made from, to rebuild it only when that changes.
  struct OverlayKey {
    Overlay overlay = Overlay::None;
    int selected = -1;
    uint64_t version = UINT64_MAX;
    uint64_t renderer = 0;  // Session::renderer_id(): a new session or renderer starts over
    bool operator==(const OverlayKey&) const = default;
  } m_overlay_key;
  bool m_overlay_on = false;
  bool m_swapchain_stale = false;     // the last present found the swapchain out of date
  VkExtent2D m_requested_size{};      // the window size the swapchain was last made for
  Timer m_spp_timer;                  // the status line's mean spp: when it was read
  bool m_mean_spp_converged = false;  // and whether the image had converged then
};

// Where the File panel saves unless told: beside the source, "_edited" before its extension.
std::string default_save_path(const std::filesystem::path& source);

}  // namespace hipr::viewer
