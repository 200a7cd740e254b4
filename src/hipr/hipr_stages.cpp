#include "hipr/hipr_stages.h"

#include <algorithm>

#include "core/error.h"
#include "shaders/shared/bindings/trace.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

HiprStages::HiprStages(RenderState& state)
    : m_state(state),
      m_active(state.ctx, state.gpu, state.tiles, state.film, state.gbuffers, state.resolve.display,
               state.tiles.weights, state.settings.width * state.settings.height),
      m_reach(state.ctx, state.gpu, state.tiles, state.gbuffers, state.resolve.display,
              m_active.tile_change, state.settings.width * state.settings.height, state.features),
      m_reproject(state.ctx, state.gpu, state.gbuffers, state.resolve.display, state.settings.width,
                  state.settings.height),
      m_discovery(state.ctx, state.gpu, state.tiles, state.film, state.resolve.display,
                  state.settings, state.features,
                  {{abi::kTraceGBuffer, &state.gbuffers.current},
                   {abi::kTraceChangedRecords, &m_active.changed_records},
                   {abi::kTraceTileWeights, &state.tiles.weights}}),
      m_schedule(state.ctx, state.gpu, state.tiles, state.tiles.weights, m_active.tile_change,
                 m_active.tile_focus) {
  state.tiles.weights.clear();
  // The first edit's "before": the G-buffer the engine already rendered (its picking, a refresh),
  // which shows the scene as it was then, or else the scene as it is now.
  state.rendered_gbuffers();
}

HiprStages& hipr_stages(RenderState& state) {
  if (!state.extension) {
    auto stages = std::make_unique<HiprStages>(state);
    stages->warm_up();
    state.extension = std::move(stages);
  }
  auto* stages = dynamic_cast<HiprStages*>(state.extension.get());
  if (!stages) throw InternalError("the render holds another method's passes");
  return *stages;
}

HiprStages& hipr_stages(ProgressiveRenderer& renderer) {
  RenderState* state = renderer.render_state();
  if (!state)
    throw InputError("the hipr policy needs HiPR's stages: hipr's renderer, or make_hipr_policy");
  return hipr_stages(*state);
}

void HiprStages::kernel_features_changed(uint32_t features) {
  m_discovery.set_features(features);
  m_reach.set_kernel_features(features);
  warm_up();
}

uint32_t HiprStages::stage1_visibility(const ChangeSet& changes) {
  // What no G-buffer shows (a moved camera, the environment's reach) makes every tile active.
  // Changed punctual lights are followed to the surfaces they reach (light_reach.comp). A camera
  // edit alone reuses the image before it, reprojected (reproject_display.comp); its rejected
  // pixels score, the rest follow by distance.
  const bool everything =
      changes.camera || changes.environment || !LightReachPass::can_follow(changes);
  m_reach.set_changed(everything ? ChangeSet{} : changes);
  return mark_tiles(changes, everything ? abi::kCarryEverything : abi::kCarryEdit, true,
                    m_reprojection && changes.camera_only() ? &changes.camera_before : nullptr,
                    changes.transforms || changes.geometry);
}

uint32_t HiprStages::stage1_focus() {
  // The G-buffer shows the scene as it is unless a policy without stage 1 left it behind.
  if (!m_state.gbuffers.is_current()) m_state.gbuffers.render();
  m_reach.set_changed({});
  return mark_tiles({}, abi::kCarryRefocus, false);
}

void HiprStages::set_focus(const Focus& focus) { m_focus = focus; }

uint32_t HiprStages::mark_tiles(const ChangeSet& changes, uint32_t carry_mode, bool render_gbuffer,
                                const Camera* reproject_from, bool moved) {
  if (m_active.set_changed(m_state.gpu, changes, m_focus)) m_discovery.rebind();
  m_state.ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    if (render_gbuffer) {
      m_state.gbuffers.record_keep_previous(cmd);
      vk::transfer_to_compute_barrier(cmd);
    }
    m_active.record_carry(cmd, carry_mode);
    if (render_gbuffer) m_state.gbuffers.record(cmd);
    vk::compute_to_compute_barrier(cmd);
    if (reproject_from) {
      m_reproject.record(cmd, *reproject_from);
      vk::compute_to_compute_barrier(cmd);
    }
    // After a reprojection the screen shows the new view: a pixel showing a surface it does not
    // see (a rejected one) scores, as after any edit.
    m_active.record(cmd, carry_mode == abi::kCarryEverything && !reproject_from,
                    reproject_from != nullptr, moved);
    vk::compute_to_compute_barrier(cmd);
    m_reach.record(cmd);
  });
  // What the CPU needs: stage 2 is split into steps of equal work over |A| tiles, and the
  // focus's lead comes after the scored ones among them.
  const std::vector<uint32_t> flags = m_state.tiles.flags.download_all<uint32_t>();
  uint32_t active = 0;
  m_seeded = 0;
  m_lead_tiles = 0;
  for (uint32_t f : flags) {
    if ((f & abi::kTileActive) == 0) continue;
    ++active;
    if (f & abi::kTileScored) ++m_seeded;
    if (f & abi::kTileEditLead) ++m_lead_tiles;
  }
  return active;
}

void HiprStages::stage2_discover(uint32_t offset, uint32_t count, uint32_t samples_per_pixel,
                                 std::optional<DisplayRule> then_resolve) {
  m_state.trace_entries(m_discovery, offset, count, samples_per_pixel, abi::kTileActive, 0u,
                        then_resolve);
}

void HiprStages::build_schedule() {
  m_state.ctx.submit_and_wait([&](VkCommandBuffer cmd) { m_schedule.record(cmd); });
}

uint32_t HiprStages::discovered_tiles() const {
  // The discovered tiles that changed strongly: the edit's lead waits for their first visit
  // (Scheduler::begin_edit_lead). Weights fall off smoothly from the strongest (a moved object's
  // old shadow) to faint colour bleeding that reaches everywhere in a closed room; a sixteenth
  // of the strongest is where they stop being worth more than the lead. Read back only when
  // asked (an edit with a lead), not at every sort.
  const std::vector<uint32_t> flags = m_state.tiles.flags.download_all<uint32_t>();
  const std::vector<uint64_t> weights = m_state.tiles.weights.download_all<uint64_t>();
  const auto discovered = [&](size_t t) {
    return (flags[t] & abi::kTileDiscovered) && !(flags[t] & abi::kTileActive);
  };
  uint64_t strongest = 0;
  for (size_t t = 0; t < flags.size(); ++t)
    if (discovered(t)) strongest = std::max(strongest, weights[t]);
  uint32_t strong = 0;
  for (size_t t = 0; t < flags.size(); ++t)
    if (discovered(t) && weights[t] * 16 >= strongest) ++strong;
  return strong;
}

void HiprStages::warm_up() {
  if (!m_state.settings.compile_kernels_early) return;
  m_state.ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m_discovery.record(cmd, no_tile_push(m_discovery, m_state.tiles.count()));
    m_schedule.record_warm_up(cmd);
    m_reach.record_warm_up(cmd);
    m_reproject.prepare();
  });
}

}  // namespace hipr
