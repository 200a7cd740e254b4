// The viewer's files: the scene it opens and saves, screenshots, the frames and statistics
// that --frames-dir and --stats-json ask for.
#include <algorithm>
#include <cstdio>

#include "app/viewer/screenshot.h"
#include "app/viewer/viewer_app.h"
#include "core/error.h"
#include "core/file_util.h"
#include "core/log.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "image/builtin_environments.h"
#include "image/image_io.h"

namespace hipr::viewer {
namespace fs = std::filesystem;

std::string default_save_path(const fs::path& source) {
  const fs::path dir = source.has_parent_path() ? source.parent_path() : fs::path(".");
  return (dir / (source.stem().string() + "_edited" + source.extension().string())).string();
}

void Viewer::open_scene() {
  m_state.request_open = false;
  const fs::path path = m_state.open_path;
  // The current scene stays until the new one is loaded and on the GPU: a bad file loses nothing.
  try {
    Scene scene = load_scene(path, m_options.common.load);
    SessionSettings settings = m_session->settings();
    auto session = std::make_unique<Session>(m_ctx, std::move(scene), settings);
    vkDeviceWaitIdle(m_ctx.device());  // a frame in flight may read the old renderer's display
    m_session = std::move(session);
    m_state.selected_node = -1;
    m_state.emitters.clear();
    m_state.save_path = default_save_path(path);
    m_window.set_title("hipr view - " + path.filename().string());
    m_state.info("opened " + path.string());
  } catch (const std::exception& e) {
    m_state.error("cannot open " + path.string() + ": " + e.what());
  }
}

void Viewer::save_scene_file() {
  m_state.request_save = false;
  const fs::path path = m_state.save_path;
  // save_scene writes atomically (temp file + rename): a failure leaves any old file intact,
  // and the scene and its edits stay in the session either way.
  try {
    save_scene(m_session->scene(), path);
    m_session->mark_saved();
    m_state.info("saved " + path.string());
    // The environment comes from --env, not from glTF: say how to get it and its edits back.
    if (m_session->scene().environment)
      m_state.info("glTF has no environment: reopen with " + environment_flags(m_session->scene()));
  } catch (const std::exception& e) {
    m_state.error("cannot save " + path.string() + ": " + e.what());
  }
}

void Viewer::take_screenshot(const fs::path& path) {
  try {
    m_presenter->wait_idle();
    save_screenshot(path, m_ctx, m_frame, m_session->shown(m_state.denoise));
    m_state.info("screenshot " + path.string());
  } catch (const InputError& e) {
    m_state.error(e.what());
  }
}

void Viewer::meter_exposure(uint32_t frame_index) {
  if (!m_state.auto_exposure) return;
  // Metered on the device (4 KB read back); every eighth frame is as often as it needs.
  if (frame_index >= 4 && frame_index % 8 != 0) return;
  follow_metering(m_state, m_session->metered_exposure());
}

void Viewer::dump_frame(uint32_t frame_index, double frame_seconds) {
  char name[32];
  std::snprintf(name, sizeof(name), "frame_%05u.exr", frame_index);
  write_image(m_options.frames_dir / name, m_session->shown(m_state.denoise));
  m_frame_log.push_back({{"frame", frame_index},
                         {"file", name},
                         {"script_edits", m_script_next},
                         {"frame_ms", frame_seconds * 1e3}});
}

void Viewer::write_frame_log() const {
  write_text_atomically(m_options.frames_dir / "frames.json", m_frame_log.dump(1) + "\n");
}

// The frames that ran scheduling steps: how many, their rate and the spread of their times (ms).
nlohmann::json Viewer::rendering_stats() const {
  std::vector<double> ms = m_rendering_frame_ms;
  if (ms.empty()) return {{"frames", 0}};
  std::sort(ms.begin(), ms.end());
  double total = 0.0;
  for (double m : ms) total += m;
  const auto at = [&ms](double q) {
    return ms[std::min(ms.size() - 1, size_t(q * double(ms.size())))];
  };
  return {{"frames", ms.size()},
          {"fps", total > 0.0 ? 1e3 * double(ms.size()) / total : 0.0},
          {"frame_ms_median", at(0.5)},
          {"frame_ms_p95", at(0.95)},
          {"frame_ms_max", ms.back()},
          {"allocations_per_frame", double(m_rendering_counts.allocations) / double(ms.size())},
          {"submissions_per_frame", double(m_rendering_counts.submissions) / double(ms.size())}};
}

void Viewer::write_stats(double seconds) const {
  const size_t rendering = m_rendering_frame_ms.size();
  nlohmann::json edits = nlohmann::json::array();
  for (const EditRecord& r : m_session->edit_records())
    edits.push_back({{"edit", r.what},
                     {"latency_seconds", r.latency_seconds},
                     {"work_at_first_change", r.work_at_first_change},
                     {"steps_at_first_change", r.steps_at_first_change}});
  const RenderSettings& s = m_options.common.render;
  const nlohmann::json stats = {
      {"device", m_ctx.device_name()},
      {"traversal", m_ctx.traversal_name()},
      {"presentation", m_presenter->description()},
      {"width", s.width},
      {"height", s.height},
      {"policy", policy_name(m_session->settings().schedule.policy)},
      {"first_frame_seconds", m_first_frame_seconds},
      {"frames", m_frames},
      {"seconds", seconds},
      {"fps", seconds > 0.0 ? double(m_frames) / seconds : 0.0},
      {"steps", m_steps},
      {"rendering", rendering_stats()},
      {"host_transfer_bytes_per_frame",
       rendering ? double(m_rendering_counts.transfer_bytes) / double(rendering) : 0.0},
      {"edits", edits}};
  write_text_atomically(m_options.stats_json, stats.dump(2) + "\n");
}

}  // namespace hipr::viewer
