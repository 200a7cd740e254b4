#include "app/viewer/viewer_app.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>
#include <functional>
#include <glm/trigonometric.hpp>
#include <memory>
#include <nlohmann/json.hpp>

#include "app/viewer/panels.h"
#include "app/viewer/screenshot.h"
#include "app/viewer/session.h"
#include "app/viewer/ui_layer.h"
#include "app/viewer/view_layout.h"
#include "app/viewer/viewer_state.h"
#include "app/viewer/viewport_input.h"
#include "app/viewer/window.h"
#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "core/timer.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "image/builtin_environments.h"
#include "render/display_pass.h"
#include "render/viewer_sources.h"
#include "vk/buffer.h"
#include "vk/image.h"
#include "vk/offscreen_presenter.h"
#include "vk/swapchain.h"
#include "vk/ui_pass.h"

namespace hipr::viewer {
namespace {
namespace fs = std::filesystem;

vk::ContextOptions presenting_context_options(const app::CommonOptions& common,
                                              const Window& window) {
  vk::ContextOptions options = app::context_options(common);
  if (window.headless()) return options;
  options.instance_extensions = window.required_instance_extensions();
  options.create_surface = [&window](VkInstance instance) {
    return window.create_surface(instance);
  };
  return options;
}

std::unique_ptr<vk::Presenter> make_presenter(const vk::Context& ctx, const Window& window) {
  if (window.headless())
    return std::make_unique<vk::OffscreenPresenter>(ctx, window.framebuffer_size());
  return std::make_unique<vk::Swapchain>(ctx, window.framebuffer_size());
}

Window make_window(const ViewerOptions& options, const std::string& title, uint32_t width,
                   uint32_t height) {
  if (options.headless) return Window(Window::Headless{}, width, height);
  return Window(title, width, height);
}

}  // namespace

Viewer::Viewer(const ViewerOptions& options, Scene scene)
    : m_started(),
      m_options(options),
      m_window(make_window(options, "hipr view - " + scene.source.filename().string(),
                           window_width(options), window_height(options))),
      m_ctx(presenting_context_options(options.common, m_window)),
      m_presenter(make_presenter(m_ctx, m_window)),
      m_ui_pass(m_ctx, kFrameFormat),
      m_frame(m_ctx, m_presenter->extent(), kFrameFormat, kFrameUsage),
      m_ui(m_window, m_ctx, m_ui_pass, *m_presenter),
      m_display(m_ctx, options.common.render.width, options.common.render.height),
      m_requested_size(m_window.framebuffer_size()) {
  m_ui_pass.set_target(m_frame);
  SessionSettings settings;
  settings.render = options.common.render;
  settings.schedule = options.schedule;
  settings.spp = options.common.spp;
  settings.converge = options.converge;
  m_state.open_path = scene.source.string();
  m_state.save_path = default_save_path(scene.source);
  m_state.screenshot_path =
      options.screenshot.empty() ? "hipr_screenshot.png" : options.screenshot.string();
  m_state.overlay = options.overlay;
  m_state.exposure_ev = options.display.exposure_ev.value_or(0.0f);
  m_state.auto_exposure = !options.display.exposure_ev;
  m_state.tone_mapper = options.display.tone_mapper;
  m_state.show_ui = options.show_ui;
  m_state.denoise = options.denoise;
  m_state.frame_budget_ms = options.frame_budget_ms;
  m_state.steps_per_frame = options.steps_per_frame;
  m_state.hipr_sliders = options.common.render.hipr;
  m_state.tile_size_input = int(options.common.render.tile_size);
  m_state.preset = options.common.preset.empty() ? "default" : options.common.preset;
  m_state.selected_node = options.select;
  m_state.focus_selection = options.focus_selection;
  // The session compiles the kernels (lavapipe: up to minutes on a first start): say so.
  show_message("Preparing " + scene.source.filename().string() +
               ":\ncompiling the path tracer (the first start with a scene can take a minute or "
               "two on a CPU)");
  m_session = std::make_unique<Session>(m_ctx, std::move(scene), settings);
  // The denoiser's pass and the exposure meter made (and compiled) now, not in the first frame
  // that renders.
  if (m_state.denoise.enabled) m_session->denoised_display();
  if (m_state.auto_exposure) m_session->metered_exposure();
  log::info("viewer on " + m_ctx.device_name() + " (" + m_ctx.traversal_name() + " traversal), " +
            m_presenter->description());
}

ViewLayout Viewer::layout() const {
  const VkExtent2D extent = m_frame.extent();
  const uint32_t panel = m_state.show_ui ? uint32_t(kPanelWidth * m_window.pixel_ratio()) : 0u;
  const uint32_t area = extent.width > panel ? extent.width - panel : extent.width;
  return fit_view(m_options.common.render.width, m_options.common.render.height, area,
                  extent.height);
}

void Viewer::resize(VkExtent2D extent) {
  // Minimised: nothing to present to; the loop resizes again once the window has a size.
  if (extent.width == 0 || extent.height == 0) return;
  m_requested_size = extent;
  m_swapchain_stale = false;
  m_presenter->recreate(extent);
  m_ui.set_min_image_count(m_presenter->min_image_count());
  m_frame = vk::Image(m_ctx, m_presenter->extent(), kFrameFormat, kFrameUsage);
  m_ui_pass.set_target(m_frame);
}

// A centred text on the background (before there is an image). Two frames: ImGui sizes a new
// auto-sized window in its first frame and draws it from the second.
void Viewer::show_message(const std::string& text) {
  for (int i = 0; i < 2; ++i) show_message_frame(text);
}

void Viewer::show_message_frame(const std::string& text) {
  m_ui.new_frame({});
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x * 0.5f, io.DisplaySize.y * 0.5f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin("message", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoInputs);
  ImGui::TextUnformatted(text.c_str());
  ImGui::End();
  const auto frame = m_presenter->begin_frame();
  if (!frame) {
    ImGui::EndFrame();
    return;
  }
  DisplayView view;
  view.output_width = m_frame.extent().width;
  view.output_height = m_frame.extent().height;
  view.x = int(view.output_width);  // no image yet: the background everywhere
  draw_and_present(*frame, view);   // an out-of-date swapchain is rebuilt by the next present()
}

// Records the display pass and the UI on top into the frame image, then presents it. False when
// the swapchain turned out of date.
bool Viewer::draw_and_present(const vk::PresentFrame& frame, const DisplayView& view) {
  m_display.record(frame.cmd, view);
  vk::record_buffer_to_image(frame.cmd, m_display.output(), m_frame);
  m_ui_pass.begin(frame.cmd);
  m_ui.render(frame.cmd);
  m_ui_pass.end(frame.cmd);
  return m_presenter->present(frame, m_frame);
}

void Viewer::run_script(uint32_t frame) {
  const auto& script = m_options.script;
  const uint64_t first =
      m_options.script_start > 0 ? m_options.script_start : m_options.script_every;
  if (m_script_next >= script.size() ||
      frame != first + m_script_next * uint64_t(m_options.script_every))
    return;
  // As if typed: the same path as a panel edit (undoable, one on_edit).
  try {
    m_session->edit(script[m_script_next]);
  } catch (const InputError& e) {
    m_state.error(e.what());
  }
  ++m_script_next;
}

void Viewer::draw_ui(const ViewLayout& layout, const std::vector<KeyPress>& keys) {
  const ImGuiIO& io = ImGui::GetIO();
  m_input.update(*m_session, m_state, layout, m_window.pixel_ratio(), keys);
  if (m_state.show_ui) {
    const float panel_x = io.DisplaySize.x - kPanelWidth;
    draw_side_panel(*m_session, m_state, panel_x, io.DisplaySize.y);
    if (m_state.show_status)
      draw_status_line(*m_session, m_state, 0.0f, io.DisplaySize.y, std::max(panel_x, 0.0f));
  }
  end_ui_edit_group(*m_session, m_state);
}

void Viewer::handle_requests() {
  if (m_state.request_open && m_state.open_confirmed) open_scene();
  if (m_state.request_save) save_scene_file();
  take_setting_request(
      m_state.request_schedule, "scheduling",
      [&](const ScheduleSettings& schedule) { m_session->set_schedule(schedule); });
  take_setting_request(m_state.request_tile_size, "tile size",
                       [&](uint32_t n) { m_session->set_tile_size(n); });
  take_setting_request(m_state.request_sampler, "sampler",
                       [&](Sampler s) { m_session->set_sampler(s); });
  take_setting_request(m_state.request_light_selection, "light selection",
                       [&](LightSelection s) { m_session->set_light_selection(s); });
  take_setting_request(m_state.request_guiding, "path guiding",
                       [&](bool on) { m_session->set_guiding(on); });
  take_setting_request(m_state.request_convergence, "convergence",
                       [&](const std::pair<uint32_t, ConvergenceTarget>& request) {
                         m_session->set_convergence(request.first, request.second);
                       });
}

template <class T, class Apply>
void Viewer::take_setting_request(std::optional<T>& request, const char* what, Apply apply) {
  if (!request) return;
  try {
    apply(*request);
  } catch (const std::exception& e) {
    m_state.error(std::string("cannot change the ") + what + ": " + e.what());
  }
  request.reset();
}

void Viewer::render_steps() {
  const Timer timer;
  if (m_session->edit_shown_unpresented() && m_state.steps_per_frame == 0) {
    // A relit edit is on the display already: present it now, render from the next frame.
    // (--steps-per-frame keeps its exact count: scripted runs stay frame for frame reproducible.)
    m_state.steps_last_frame = 0;
  } else if (m_state.steps_per_frame > 0) {
    m_state.steps_last_frame = m_session->render(1e30, m_state.steps_per_frame);
  } else if (m_session->edit_awaits_first_step()) {
    // The first step after an edit shows it (HiPR: the most changed tiles): present it at once.
    // Filling the frame's budget first would add a whole frame's work to the edit's latency.
    m_state.steps_last_frame = m_session->render(1e30, 1);
  } else if (m_state.frame_budget_ms > 0.0) {
    m_state.steps_last_frame = m_session->render(m_state.frame_budget_ms * 1e-3);
  } else {
    // What a 60 fps frame leaves after the rest of the frame, as the last frames measured it: a
    // GPU that renders a step in 2 ms fits several. Where the rest alone takes longer than a
    // 60 fps frame (lavapipe: UI and presentation on the CPU), rendering gets as long as the rest,
    // up to the fixed default, so it keeps at least half of each frame (render() runs one step
    // whatever the budget).
    constexpr double kFrameMs = 1000.0 / 60.0, kSlowDeviceMs = 30.0;
    m_state.adaptive_budget_ms =
        std::max(kFrameMs - m_frame_overhead_ms, std::min(m_frame_overhead_ms, kSlowDeviceMs));
    m_state.steps_last_frame = m_session->render(m_state.adaptive_budget_ms * 1e-3);
  }
  m_render_ms = timer.seconds() * 1e3;
}

void Viewer::update_overlay() {
  const OverlayKey key{m_state.overlay, m_state.selected_node, m_session->display_version(),
                       m_session->renderer_id()};
  if (key == m_overlay_key) return;
  m_overlay_key = key;
  m_overlay_on = m_state.overlay != Overlay::None || m_state.selected_node >= 0;
  if (!m_overlay_on) return;
  // Made on the GPU from the renderer's own buffers into the display pass's overlay: showing an
  // overlay while re-rendering reads nothing back (image/debug_images.cpp's colours).
  static constexpr DebugOverlay kinds[] = {DebugOverlay::None, DebugOverlay::Ids,
                                           DebugOverlay::TileWeights, DebugOverlay::OwedTiles};
  const uint32_t selected =
      m_state.selected_node >= 0 ? uint32_t(m_state.selected_node) : UINT32_MAX;
  m_session->render_overlay(kinds[size_t(m_state.overlay)], selected, m_display.overlay_buffer());
}

// The display pass reads the renderer's display buffer itself: only a new renderer needs
// telling. Denoised, it reads the denoiser's copy, recorded again into the frame (before the
// display pass) when the display or the settings changed; once the noise target is met, the
// display itself again (Session::shows_denoised).
void Viewer::update_source(VkCommandBuffer cmd) {
  const bool denoised = m_session->shows_denoised(m_state.denoise);
  const SourceKey key{m_session->renderer_id(), denoised ? m_session->display_version() : 0,
                      denoised ? m_session->frame_denoise(m_state.denoise) : DenoiseSettings{}};
  if (key == m_source_key) return;
  const bool same_buffer =
      m_source_key.renderer == key.renderer && m_source_key.denoise.enabled == key.denoise.enabled;
  m_source_key = key;
  if (denoised) {
    if (!same_buffer) m_display.show_radiance(m_session->denoised_display());
    m_session->record_denoise(cmd, key.denoise);
  } else if (!same_buffer) {
    m_display.show(display_texels(m_session->renderer()));
  }
}

bool Viewer::present(const ViewLayout& layout) {
  const auto frame = m_presenter->begin_frame();
  if (!frame) {
    ImGui::EndFrame();
    resize(m_window.framebuffer_size());
    return false;
  }
  // The previous frame is done (begin_frame waited): its inputs may change now.
  update_source(frame->cmd);
  update_overlay();
  DisplayView view;
  view.output_width = m_frame.extent().width;
  view.output_height = m_frame.extent().height;
  view.x = layout.x;
  view.y = layout.y;
  view.scale = layout.scale;
  view.exposure_ev = m_state.exposure_ev;
  view.tone_mapper = m_state.tone_mapper;
  view.overlay = m_overlay_on;
  // Rebuilt at the next frame's start, so a screenshot of this frame still reads its image.
  if (!draw_and_present(*frame, view)) m_swapchain_stale = true;
  m_session->on_presented();
  return true;
}

int Viewer::run() {
  const Timer run_timer;
  Timer frame_timer;
  uint32_t frame_index = 0;
  while (!m_window.should_close()) {
    const vk::DeviceCounts at_frame_start = vk::DeviceCounts::now();
    const bool scripted =
        m_options.exit_after_frames > 0 || m_script_next < m_options.script.size();
    // Nothing to render and nobody in a hurry: sleep until an event instead of spinning.
    if (m_session->converged() && !scripted)
      m_window.wait_events(0.1);
    else
      m_window.poll_events();
    const VkExtent2D size = m_window.framebuffer_size();
    if (size.width == 0 || size.height == 0) {  // minimised: nothing to draw until restored
      m_window.wait_events(0.1);
      continue;
    }
    // Against the size asked for, not the one the surface granted (it may clamp it): a clamped
    // swapchain is not rebuilt every frame.
    if (m_swapchain_stale || size.width != m_requested_size.width ||
        size.height != m_requested_size.height)
      resize(size);

    const std::vector<KeyPress> keys = m_window.take_key_presses();
    for (const Window::Drop& drop : m_window.take_drops())
      drop_files(*m_session, m_state, drop.paths, drop.shift);
    m_ui.new_frame(keys);
    run_script(frame_index);
    const ViewLayout view = layout();
    draw_ui(view, keys);
    handle_requests();
    follow_environment(m_session->scene(), m_state);
    render_steps();
    meter_exposure(frame_index);
    m_steps += m_state.steps_last_frame;
    // The mean over pixels of the samples they hold, only while the status line shows it: once a
    // second, and once more when the image has converged (so that it says the final count).
    // Summed on the GPU, 8 bytes read back.
    const bool converged = m_session->converged();
    if (m_state.show_ui && m_state.show_status &&
        (m_spp_timer.seconds() > 1.0 || (converged && !m_mean_spp_converged))) {
      const RenderSettings& render = m_session->settings().render;
      m_state.mean_spp =
          double(m_session->renderer().total_samples()) / (double(render.width) * render.height);
      m_mean_spp_converged = converged;
      m_spp_timer = Timer();
    }
    if (!present(view)) continue;
    ++frame_index;
    ++m_frames;
    if (m_first_frame_seconds < 0.0) m_first_frame_seconds = m_started.seconds();
    const double frame_seconds = frame_timer.seconds();
    frame_timer = Timer();
    // The frame's work besides rendering (UI, display pass, presentation): what the adaptive
    // budget leaves room for.
    const double overhead_ms = std::max(frame_seconds * 1e3 - m_render_ms, 0.0);
    m_frame_overhead_ms =
        m_frame_overhead_ms > 0.0 ? 0.8 * m_frame_overhead_ms + 0.2 * overhead_ms : overhead_ms;
    if (m_state.steps_last_frame >
        0) {  // re-rendering: its frame time, what crossed between host and device
      m_rendering_frame_ms.push_back(frame_seconds * 1e3);
      m_rendering_counts += vk::DeviceCounts::now() - at_frame_start;
    }
    m_state.fps = m_state.fps > 0.0 ? 0.9 * m_state.fps + 0.1 / frame_seconds : 1.0 / frame_seconds;
    if (!m_options.frames_dir.empty()) {
      dump_frame(frame_index, frame_seconds);
      frame_timer = Timer();  // the read-back is not the next frame's time
    }
    if (m_state.request_screenshot) {
      m_state.request_screenshot = false;
      take_screenshot(m_state.screenshot_path);
    }
    if (m_options.exit_after_frames > 0 && frame_index >= m_options.exit_after_frames) break;
  }
  const double seconds = run_timer.seconds();
  m_presenter->wait_idle();
  // The scene first, and every output tried: a failed screenshot must not cost the edits.
  std::string failures;
  const auto attempt = [&failures](const std::function<void()>& write) {
    try {
      write();
    } catch (const InputError& e) {
      failures += (failures.empty() ? "" : "; ") + std::string(e.what());
    }
  };
  if (!m_options.save.empty()) {
    attempt([&] { save_scene(m_session->scene(), m_options.save); });
    if (m_session->scene().environment)
      log::info("glTF has no environment: reopen with " + environment_flags(m_session->scene()));
  }
  if (!m_options.screenshot.empty())
    attempt([&] {
      save_screenshot(m_options.screenshot, m_ctx, m_frame, m_session->shown(m_state.denoise));
    });
  if (!m_options.stats_json.empty()) attempt([&] { write_stats(seconds); });
  if (!m_options.frames_dir.empty()) attempt([&] { write_frame_log(); });
  app::check_validation(m_ctx);
  if (!failures.empty()) throw InputError(failures);
  return kExitOk;
}

int run_viewer(const ViewerOptions& options, Scene scene) {
  Viewer viewer(options, std::move(scene));
  return viewer.run();
}

}  // namespace hipr::viewer
