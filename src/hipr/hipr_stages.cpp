#include "hipr/hipr_stages.h"

#include <algorithm>

#include "shaders/shared/bindings/trace.h"
#include "shaders/shared/bindings/visibility.h"

namespace hipr {

abi::TracePush no_tile_push(const TracePass& pass, uint32_t tile_count) {
  abi::TracePush push = pass.push(0, tile_count, 1);
  push.requireFlags = 1u << 31;
  return push;
}

HiprStages::HiprStages(const RenderParts& parts, uint32_t kernel_features)
    : m_parts(parts),
      m_tile_weights(parts.ctx, size_t(parts.tiles.count()) * 8, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_active(parts.ctx, parts.scene, parts.tiles, parts.film, parts.gbuffers, parts.resolve.display, m_tile_weights,
               parts.settings.width * parts.settings.height),
      m_reach(parts.ctx, parts.scene, parts.tiles, parts.gbuffers, parts.resolve.display, m_active.tile_change,
              parts.settings.width * parts.settings.height, kernel_features),
      m_reproject(parts.ctx, parts.scene, parts.gbuffers, parts.resolve.display, parts.settings.width,
                  parts.settings.height),
      m_discovery(parts.ctx, parts.scene, parts.tiles, parts.film, parts.resolve.display, parts.settings, kernel_features,
                  {{abi::kTraceGBuffer, &parts.gbuffers.current},
                   {abi::kTraceChangedRecords, &m_active.changed_records},
                   {abi::kTraceTileWeights, &m_tile_weights}}),
      m_schedule(parts.ctx, parts.scene, parts.tiles, m_tile_weights, m_active.tile_change, m_active.tile_focus) {
  m_tile_weights.clear();
  parts.gbuffers.render();
}

uint32_t HiprStages::stage1_visibility(const ChangeSet& changes) {
  // What no G-buffer shows (a moved camera, the environment's reach) makes every tile active.
  // Changed punctual lights are followed to the surfaces they reach (light_reach.comp). A camera
  // edit alone reuses the image before it, reprojected (reproject_display.comp); its rejected
  // pixels score, the rest follow by distance.
  const bool everything = changes.camera || changes.environment || !LightReachPass::can_follow(changes);
  m_reach.set_changed(everything ? ChangeSet{} : changes);
  return mark_tiles(changes, everything ? abi::kCarryEverything : abi::kCarryEdit, true,
                    m_reprojection && changes.camera_only() ? &changes.camera_before : nullptr,
                    changes.transforms || changes.geometry);
}

uint32_t HiprStages::stage1_focus() {
  // The G-buffer shows the scene as it is unless a policy without stage 1 left it behind.
  if (!m_parts.gbuffers.is_current()) m_parts.gbuffers.render();
  m_reach.set_changed({});
  return mark_tiles({}, abi::kCarryRefocus, false);
}

void HiprStages::set_focus(const Focus& focus) { m_focus = focus; }

uint32_t HiprStages::mark_tiles(const ChangeSet& changes, uint32_t carry_mode, bool render_gbuffer,
                               const Camera* reproject_from, bool moved) {
  if (m_active.set_changed(m_parts.scene, changes, m_focus)) m_discovery.rebind();
  m_parts.ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    if (render_gbuffer) {
      m_parts.gbuffers.record_keep_previous(cmd);
      vk::transfer_to_compute_barrier(cmd);
    }
    m_active.record_carry(cmd, carry_mode);
    if (render_gbuffer) m_parts.gbuffers.record(cmd);
    vk::compute_to_compute_barrier(cmd);
    if (reproject_from) {
      m_reproject.record(cmd, *reproject_from);
      vk::compute_to_compute_barrier(cmd);
    }
    // After a reprojection the screen shows the new view: a pixel showing a surface it does not
    // see (a rejected one) scores, as after any edit.
    m_active.record(cmd, carry_mode == abi::kCarryEverything && !reproject_from, reproject_from != nullptr, moved);
    vk::compute_to_compute_barrier(cmd);
    m_reach.record(cmd);
  });
  // What the CPU needs: stage 2 is split into steps of equal work over |A| tiles, and the
  // focus's lead comes after the scored ones among them.
  const std::vector<uint32_t> flags = m_parts.tiles.flags.download_all<uint32_t>();
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
  const uint32_t tiles = m_parts.tiles.count();
  if (offset >= tiles || count == 0) return;
  abi::TracePush push = m_discovery.push(offset, std::min(count, tiles - offset), samples_per_pixel);
  push.requireFlags = abi::kTileActive;
  push.sampleTarget = m_parts.sample_target.round;
  push.focusTarget = m_parts.sample_target.focus;
  push.leadTarget = m_parts.sample_target.lead;
  m_parts.ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    m_discovery.record(cmd, push);
    if (then_resolve) m_parts.resolve.record(cmd, {push.listOffset, push.tileCount, push.requireFlags, 0}, *then_resolve);
  });
}

void HiprStages::build_schedule() {
  m_parts.ctx.submit_and_wait([&](VkCommandBuffer cmd) { m_schedule.record(cmd); });
}

uint32_t HiprStages::discovered_tiles() const {
  // The discovered tiles that changed strongly: the edit's lead waits for their first visit
  // (Scheduler::begin_edit_lead). Weights fall off smoothly from the strongest (a moved object's
  // old shadow) to faint colour bleeding that reaches everywhere in a closed room; a sixteenth
  // of the strongest is where they stop being worth more than the lead. Read back only when
  // asked (an edit with a lead), not at every sort.
  const std::vector<uint32_t> flags = m_parts.tiles.flags.download_all<uint32_t>();
  const std::vector<uint64_t> weights = m_tile_weights.download_all<uint64_t>();
  const auto discovered = [&](size_t t) { return (flags[t] & abi::kTileDiscovered) && !(flags[t] & abi::kTileActive); };
  uint64_t strongest = 0;
  for (size_t t = 0; t < flags.size(); ++t)
    if (discovered(t)) strongest = std::max(strongest, weights[t]);
  uint32_t strong = 0;
  for (size_t t = 0; t < flags.size(); ++t)
    if (discovered(t) && weights[t] * 16 >= strongest) ++strong;
  return strong;
}

void HiprStages::record_warm_up(VkCommandBuffer cmd) {
  m_discovery.record(cmd, no_tile_push(m_discovery, m_parts.tiles.count()));
  m_schedule.record_warm_up(cmd);
  m_reach.record_warm_up(cmd);
  m_reproject.prepare();
}

std::vector<double> HiprStages::tile_weights() const {
  const auto fixed = m_tile_weights.download_all<uint64_t>();
  std::vector<double> out(fixed.size());
  for (size_t i = 0; i < fixed.size(); ++i) out[i] = double(fixed[i]) / abi::kWeightScale;
  return out;
}

}  // namespace hipr
