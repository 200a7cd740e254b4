#include "app/viewer/session.h"

#include <algorithm>

#include "core/error.h"
#include "hipr/edit_pipeline.h"
#include "scene/default_camera.h"

namespace hipr::viewer {

uint32_t viewer_tiles_per_step(uint32_t tile_count) { return std::max(1u, (tile_count + 63) / 64); }

uint32_t default_first_visit_spp(const SessionSettings& s) {
  return std::max(s.schedule.visit_spp, std::min(2u, s.spp));
}

Session::Session(const vk::Context& ctx, Scene scene, const SessionSettings& settings)
    : m_ctx(ctx), m_settings(settings), m_scene(std::move(scene)) {
  if (m_scene.camera_node() < 0)
    apply_edit(m_scene, CameraEdit{std::nullopt, default_view(m_scene).camera_to_world});
  rebuild();
}

ScheduleSettings Session::resolved_schedule() const {
  ScheduleSettings schedule = m_settings.schedule;
  if (schedule.first_visit_spp == 0) schedule.first_visit_spp = default_first_visit_spp(m_settings);
  return schedule;
}

std::unique_ptr<Scheduler> Session::make_scheduler(Renderer& renderer) const {
  const ScheduleSettings& s = m_settings.schedule;
  // The oracle ranks tiles against a converged render of each edited scene: a benchmark's
  // tool (hipr bench), not something a viewer can have before the user edits.
  if (s.policy == Policy::Oracle)
    throw InputError("the oracle policy needs a reference image: use hipr bench");
  const uint32_t per_step =
      s.tiles_per_step ? s.tiles_per_step : viewer_tiles_per_step(renderer.tile_count());
  auto scheduler = std::make_unique<Scheduler>(renderer, s.policy, per_step, s.visit_spp);
  scheduler->configure(resolved_schedule(),
                       m_settings.spp);  // rendering pauses at spp: the focus never passes it
  return scheduler;
}

void Session::rebuild() {
  // The new renderer is complete before the old one goes: a failure leaves the session as it was.
  // Kernels compile as they are made (a longer start) rather than at the first edit (a frozen
  // window).
  RenderSettings render = m_settings.render;
  render.compile_kernels_early = true;
  auto renderer = std::make_unique<Renderer>(m_ctx, m_scene, render);
  auto scheduler = make_scheduler(*renderer);
  // What the window had made on the old renderer (the denoiser, the exposure meter) is made on
  // the new one here too, not inside its first frame: a frame allocates nothing.
  const bool had_denoiser = m_renderer && has_denoiser(*m_renderer);
  const bool had_meter = m_renderer && has_exposure_meter(*m_renderer);
  // A frame in flight may still read the old renderer's display buffer (the viewer's display
  // pass shows it in place).
  if (m_renderer) vkDeviceWaitIdle(m_ctx.device());
  m_scheduler.reset();  // it refers to the renderer
  m_renderer = std::move(renderer);
  static uint64_t next_renderer_id = 0;
  m_renderer_id = ++next_renderer_id;
  m_scheduler = std::move(scheduler);
  display_changed();
  m_ids_stale = true;
  m_gbuffer_stale = false;  // a new renderer's G-buffer is made from the scene as it is now
  m_since_edit = Timer();
  restart_noise_checks();
  update_focus();
  if (had_denoiser) denoised_display();
  if (had_meter) metered_exposure();
}

void Session::changed(const std::function<void(Scene&)>& change, const std::string& what) {
  const Timer started;  // the latency includes on_edit itself (GPU update, stage 1)
  const std::vector<Instance> before =
      m_script_focus.empty() ? std::vector<Instance>{} : m_scene.instances();
  // The pipeline renumbers the scheduler's focus for the edit's plan when instances come or go.
  if (EditPipeline(m_scene, *m_scheduler, m_scheduler->focus()).apply(change).empty())
    return;                       // e.g. a slider released where it started
  if (!m_script_focus.empty()) {  // a duplicate or delete renumbers the instances the seeds name
    m_script_focus = follow_instances(m_script_focus, before, m_scene.instances());
    update_focus();
  }
  m_awaiting_change = true;
  m_steps_since_edit = 0;
  m_since_edit = started;
  restart_noise_checks();
  display_changed();
  m_ids_stale = true;
  // HiPR's on_edit runs stage 1, which renders the G-buffer of the edited scene; the other
  // policies leave it as it was (scheduler.h).
  if (m_settings.schedule.policy != Policy::Hipr) m_gbuffer_stale = true;
  m_records.push_back({what});
  m_bounds.reset();
}

std::pair<glm::vec3, glm::vec3> Session::bounds() const {
  if (!m_bounds) m_bounds = m_scene.bounds();
  return *m_bounds;
}

float Session::radius() const {
  const auto [lo, hi] = bounds();
  return std::max(0.5f * glm::length(hi - lo), 1e-6f);
}

void Session::edit(const Edit& edit) {
  if (const auto* focus = std::get_if<FocusEdit>(&edit)) {
    m_script_focus = with_focus_edit(m_scene, m_script_focus, *focus);
    update_focus();
    return;
  }
  changed([&](Scene& scene) { m_history.apply(scene, edit); }, describe(edit));
}

bool Session::undo() {
  const std::string what = "undo " + m_history.undo_label();
  bool undone = false;
  changed([&](Scene& scene) { undone = m_history.undo(scene); }, what);
  return undone;
}

bool Session::redo() {
  const std::string what = "redo " + m_history.redo_label();
  bool redone = false;
  changed([&](Scene& scene) { redone = m_history.redo(scene); }, what);
  return redone;
}

bool Session::converged() const {
  if (m_scheduler->work_since_edit() >= double(m_settings.spp)) return true;
  if (!may_pause_early()) return false;
  const ConvergenceTarget& target = m_settings.converge;
  if (target.seconds > 0.0 && m_since_edit.seconds() >= target.seconds) return true;
  return m_noise_met;
}

bool Session::may_pause_early() const {
  return m_scheduler->rounds_since_edit() > 0 && m_scheduler->at_round_end();
}

void Session::restart_noise_checks() {
  m_noise.reset();
  m_noise_met = false;
  m_next_noise_check = 2.0;  // no pixel has two samples before two passes' work
}

void Session::check_noise() {
  const double target = m_settings.converge.relmse;
  if (target <= 0.0 || m_noise_met || !may_pause_early()) return;
  const double work = m_scheduler->work_since_edit();
  if (work < m_next_noise_check) return;
  m_noise = m_renderer->noise();
  m_noise_met = m_noise->within(target);
  if (m_noise->unknown_pixels > 0) {  // a pixel with one sample: look again a pass later
    m_next_noise_check = work + 1.0;
    return;
  }
  // The relMSE of a mean falls as 1/samples: the next look is where this estimate meets the
  // target, a little early (a sample variance of few samples misses rare paths), at least 10 %
  // later and at most 4x (an early estimate can also be too high).
  const double needed = work * m_noise->relmse / target;
  m_next_noise_check = std::clamp(0.9 * needed, 1.1 * work, 4.0 * work);
}

void Session::set_convergence(uint32_t spp, const ConvergenceTarget& target) {
  const ScheduleSettings schedule = resolved_schedule();
  m_settings.spp = std::max({spp, schedule.visit_spp, schedule.first_visit_spp, 1u});
  // What is shown once clean changes no target: a met one stays met.
  ConvergenceTarget before = m_settings.converge, after = target;
  before.keep_denoised = after.keep_denoised = false;
  const bool targets_changed = !(before == after);
  m_settings.converge = target;
  m_scheduler->configure(resolved_schedule(), m_settings.spp);
  if (targets_changed) restart_noise_checks();
}

uint32_t Session::render(double budget_seconds, uint32_t max_steps) {
  const Timer timer;
  uint32_t steps = 0;
  while (steps < max_steps && !converged()) {
    const double started = timer.seconds();
    m_scheduler->step();
    ++steps;
    ++m_steps_since_edit;
    display_changed();
    check_noise();
    // Stop before a step that would overrun the budget, not after: on a GPU a step takes a few
    // milliseconds, and overrunning a 60 fps frame by one drops the frame rate below 60.
    const double elapsed = timer.seconds();
    if (elapsed + (elapsed - started) > budget_seconds) break;
  }
  return steps;
}

double Session::samples_per_second() const {
  const double seconds = m_since_edit.seconds();
  const double samples =
      m_scheduler->work_since_edit() * m_settings.render.width * m_settings.render.height;
  return seconds > 0.0 ? samples / seconds : 0.0;
}

const ImageRGB& Session::displayed() {
  if (m_displayed_version != m_display_version) {
    m_displayed = m_scheduler->displayed_image();
    m_displayed_version = m_display_version;
  }
  return m_displayed;
}

float Session::metered_exposure() {
  if (m_metering.renderer != m_renderer_id || m_metering.version != m_display_version)
    m_metering = {m_renderer_id, m_display_version, metered_display_exposure(*m_renderer)};
  return m_metering.ev;
}

bool Session::shows_denoised(const DenoiseSettings& denoise) const {
  if (!denoise.enabled) return false;
  if (m_settings.converge.keep_denoised) return true;
  return !(converged() && m_noise_met && m_noise->relmse <= kRawIsCleanerRelmse);
}

ImageRGB Session::shown(const DenoiseSettings& denoise) {
  return shows_denoised(denoise) ? m_renderer->denoised_image(frame_denoise(denoise)) : displayed();
}

DenoiseSettings Session::frame_denoise(const DenoiseSettings& denoise) const {
  return converged() ? without_history(denoise) : denoise;
}

bool Session::edit_shown_unpresented() const {
  return edit_awaits_first_step() && m_scheduler->relit();
}

void Session::on_presented() {
  // The first step after an edit resolves the tiles it rendered to the display (HiPR: the most
  // changed ones): the frame presented after it is the first to show the change; a relit edit
  // shows at once. Judged without reading the image back, so presenting costs no host transfer.
  if (!m_awaiting_change || m_records.empty() ||
      (edit_awaits_first_step() && !m_scheduler->relit()))
    return;
  m_records.back().latency_seconds = m_since_edit.seconds();
  m_records.back().work_at_first_change = m_scheduler->work_since_edit();
  m_records.back().steps_at_first_change = m_steps_since_edit;
  m_awaiting_change = false;
}

void Session::render_overlay(DebugOverlay overlay, uint32_t selected_node,
                             const vk::Buffer& output) {
  if (overlay == DebugOverlay::Ids || selected_node != UINT32_MAX) ensure_gbuffer();
  hipr::render_overlay(*m_renderer, overlay, selected_node, output);
}

const vk::Buffer& Session::denoised_display() { return hipr::denoised_display(*m_renderer); }

void Session::record_denoise(VkCommandBuffer cmd, const DenoiseSettings& settings) {
  hipr::record_denoise(*m_renderer, cmd, frame_denoise(settings));
}

void Session::ensure_gbuffer() {
  if (!m_gbuffer_stale) return;
  m_renderer->refresh_gbuffer();
  m_gbuffer_stale = false;
  m_ids_stale = true;
}

const std::vector<uint32_t>& Session::instance_ids() {
  ensure_gbuffer();
  if (m_ids_stale) {
    m_ids = m_renderer->gbuffer_instances();
    m_ids_stale = false;
  }
  return m_ids;
}

Renderer::PixelHit Session::pick(uint32_t x, uint32_t y) {
  ensure_gbuffer();
  return m_renderer->gbuffer_at(x, y);
}

void Session::set_view_focus(const Focus& focus) {
  m_view_focus = focus;
  update_focus();
}

void Session::update_focus() {
  Focus focus = m_script_focus;
  focus.seeds.insert(focus.seeds.end(), m_view_focus.seeds.begin(), m_view_focus.seeds.end());
  if (focus == m_scheduler->focus()) return;
  m_scheduler->set_focus(focus);
  display_changed();
}

void Session::set_schedule(const ScheduleSettings& schedule) {
  const ScheduleSettings& now = m_settings.schedule;
  if (schedule.policy == now.policy && schedule.tiles_per_step == now.tiles_per_step &&
      schedule.visit_spp == now.visit_spp) {
    m_settings.schedule = schedule;
    m_scheduler->configure(resolved_schedule(), m_settings.spp);
    return;
  }
  const ScheduleSettings previous = now;
  m_settings.schedule = schedule;
  try {
    m_scheduler = make_scheduler(*m_renderer);
  } catch (...) {
    m_settings.schedule = previous;
    throw;
  }
  restart_noise_checks();  // the new scheduler's work starts at zero
  update_focus();
  // A HiPR scheduler starts with stage 1 of the scene as it is now.
  if (schedule.policy == Policy::Hipr) m_gbuffer_stale = false;
  m_ids_stale = true;
  display_changed();
}

void Session::set_tile_size(uint32_t tile_size) {
  if (tile_size < 1 || tile_size > 256) throw InputError("tile size must be between 1 and 256");
  if (tile_size == m_settings.render.tile_size) return;
  SessionSettings next = m_settings;
  next.render.tile_size = tile_size;
  rebuild_with(next);
}

void Session::set_sampler(Sampler sampler) {
  if (sampler == m_settings.render.sampler) return;
  SessionSettings next = m_settings;
  next.render.sampler = sampler;
  rebuild_with(next);
}

void Session::set_light_selection(LightSelection selection) {
  if (selection == m_settings.render.light_selection) return;
  SessionSettings next = m_settings;
  next.render.light_selection = selection;
  rebuild_with(next);
}

void Session::set_guiding(bool guiding) {
  if (guiding == m_settings.render.guiding) return;
  SessionSettings next = m_settings;
  next.render.guiding = guiding;
  rebuild_with(next);
}

void Session::rebuild_with(const SessionSettings& settings) {
  const SessionSettings previous = m_settings;
  m_settings = settings;
  try {
    rebuild();
  } catch (...) {
    m_settings = previous;  // a renderer that cannot be made leaves the session as it was
    throw;
  }
}

void Session::set_hipr_parameters(const HiprParameters& parameters) {
  m_settings.render.hipr = parameters;
  m_renderer->set_hipr_parameters(parameters);
}

}  // namespace hipr::viewer
