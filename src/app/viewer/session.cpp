#include "app/viewer/session.h"

#include <algorithm>

#include "core/error.h"
#include "hipr/scene_diff.h"
#include "scene/default_camera.h"

namespace hipr::viewer {

uint32_t default_tiles_per_step(uint32_t tile_count) {
  return std::max(1u, (tile_count + 63) / 64);
}

uint32_t default_first_visit_spp(const SessionSettings& s) {
  return std::max(s.visit_spp, std::min(2u, s.spp));
}

Scene diff_snapshot(const Scene& scene) {
  Scene s;
  s.source = scene.source;
  s.nodes = scene.nodes;
  s.materials = scene.materials;
  s.lights = scene.lights;
  s.cameras = scene.cameras;
  s.root_nodes = scene.root_nodes;
  s.children = scene.children;
  // Without a camera node the default camera frames the scene's bounds: keep positions then.
  const bool need_positions = scene.camera_node() < 0;
  s.meshes.reserve(scene.meshes.size());
  for (const Mesh& mesh : scene.meshes) {
    Mesh copy;
    copy.name = mesh.name;
    for (const MeshPrimitive& primitive : mesh.primitives) {
      MeshPrimitive p;
      p.material = primitive.material;
      if (need_positions) p.positions = primitive.positions;
      copy.primitives.push_back(std::move(p));
    }
    s.meshes.push_back(std::move(copy));
  }
  if (scene.environment) {
    Environment env;
    env.path = scene.environment->path;
    env.intensity = scene.environment->intensity;
    env.rotation = scene.environment->rotation;
    s.environment = std::move(env);
  }
  return s;
}

Session::Session(const vk::Context& ctx, Scene scene, const SessionSettings& settings)
    : m_ctx(ctx), m_settings(settings), m_scene(std::move(scene)) {
  if (m_scene.camera_node() < 0)
    apply_edit(m_scene, CameraEdit{std::nullopt, resolve_camera(m_scene).camera_to_world});
  rebuild();
}

std::unique_ptr<Scheduler> Session::make_scheduler(Renderer& renderer, Policy policy) const {
  // The oracle ranks tiles against a converged render of each edited scene: a benchmark's
  // tool (hipr bench), not something a viewer can have before the user edits.
  if (policy == Policy::Oracle)
    throw InputError("the oracle policy needs a reference image: use hipr bench");
  const uint32_t per_step = m_settings.tiles_per_step
                                ? m_settings.tiles_per_step
                                : default_tiles_per_step(renderer.tile_count());
  auto scheduler = std::make_unique<Scheduler>(renderer, policy, per_step, m_settings.visit_spp);
  scheduler->set_display_rule(m_settings.display.value_or(default_display_rule(policy)));
  scheduler->set_first_visit_spp(m_settings.first_visit_spp ? m_settings.first_visit_spp
                                                            : default_first_visit_spp(m_settings));
  return scheduler;
}

void Session::rebuild() {
  // The new renderer is complete before the old one goes: a failure leaves the session as it was.
  auto renderer = std::make_unique<Renderer>(m_ctx, m_scene, m_settings.render);
  auto scheduler = make_scheduler(*renderer, m_settings.policy);
  // Compile the kernels now (a longer start) rather than at the first edit (a frozen window).
  renderer->warm_up_kernels();
  m_scheduler.reset();  // it refers to the renderer
  m_renderer = std::move(renderer);
  m_scheduler = std::move(scheduler);
  m_dirty_display = true;
  m_ids_stale = true;
  m_gbuffer_stale = false;  // a new renderer's G-buffer is made from the scene as it is now
  m_since_edit = Timer();
}

void Session::changed(const Scene& before, const std::string& what) {
  const ChangeSet changes = diff_scenes(before, m_scene);
  if (changes.empty()) return;  // e.g. a slider released where it started
  m_shown_at_edit = displayed();
  const Timer started;  // the latency includes on_edit itself (GPU update, stage 1)
  m_scheduler->on_edit(m_scene, changes);
  m_since_edit = started;
  m_dirty_display = true;
  m_ids_stale = true;
  // HiPR's on_edit runs stage 1, which renders the G-buffer of the edited scene; the other
  // policies leave it as it was (scheduler.h).
  if (m_settings.policy != Policy::Hipr) m_gbuffer_stale = true;
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
  const Scene before = diff_snapshot(m_scene);
  m_history.apply(m_scene, edit);
  changed(before, describe(edit));
}

bool Session::undo() {
  const Scene before = diff_snapshot(m_scene);
  const std::string what = "undo " + m_history.undo_label();
  if (!m_history.undo(m_scene)) return false;
  changed(before, what);
  return true;
}

bool Session::redo() {
  const Scene before = diff_snapshot(m_scene);
  const std::string what = "redo " + m_history.redo_label();
  if (!m_history.redo(m_scene)) return false;
  changed(before, what);
  return true;
}

bool Session::converged() const { return m_scheduler->work_since_edit() >= double(m_settings.spp); }

uint32_t Session::render(double budget_seconds, uint32_t max_steps) {
  const Timer timer;
  uint32_t steps = 0;
  while (steps < max_steps && !converged()) {
    m_scheduler->step();
    ++steps;
    m_dirty_display = true;
    if (timer.seconds() >= budget_seconds) break;
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
  if (m_dirty_display) {
    m_displayed = m_scheduler->displayed_image();
    m_dirty_display = false;
    ++m_display_version;
  }
  return m_displayed;
}

void Session::on_presented() {
  if (!m_shown_at_edit || m_records.empty()) return;
  if (m_displayed.rgb == m_shown_at_edit->rgb) return;
  m_records.back().latency_seconds = m_since_edit.seconds();
  m_records.back().work_at_first_change = m_scheduler->work_since_edit();
  m_shown_at_edit.reset();
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

void Session::set_policy(Policy policy) {
  if (policy == m_settings.policy) return;
  m_scheduler = make_scheduler(*m_renderer, policy);
  m_settings.policy = policy;
  // A HiPR scheduler starts with stage 1 of the scene as it is now.
  if (policy == Policy::Hipr) m_gbuffer_stale = false;
  m_ids_stale = true;
  m_dirty_display = true;
}

void Session::set_display_rule(std::optional<DisplayRule> rule) {
  m_settings.display = rule;
  m_scheduler->set_display_rule(rule.value_or(default_display_rule(m_settings.policy)));
}

void Session::set_tile_size(uint32_t tile_size) {
  if (tile_size < 1 || tile_size > 256) throw InputError("tile size must be between 1 and 256");
  if (tile_size == m_settings.render.tile_size) return;
  const SessionSettings previous = m_settings;
  m_settings.render.tile_size = tile_size;
  try {
    rebuild();
  } catch (...) {
    m_settings = previous;
    throw;
  }
}

void Session::set_hipr_parameters(const HiprParameters& parameters) {
  m_settings.render.hipr = parameters;
  m_renderer->set_hipr_parameters(parameters);
}

}  // namespace hipr::viewer
