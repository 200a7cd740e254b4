#include "render/resolve_pass.h"

#include "shaders/shared/bindings/resolve.h"

namespace hipr {
namespace {

// Switch rule: a tile switches to its fresh estimate when D > kSwitchThreshold * V
// (resolve_display.comp): 2 means the stale estimate's squared error B = D - V exceeds V.
constexpr float kSwitchThreshold = 2.0f;

// The kernel's rule (abi::kDisplay*). Without difference records the difference rule is blend.
uint32_t kernel_rule(DisplayRule rule, bool difference) {
  switch (rule) {
    case DisplayRule::Immediate:
      return abi::kDisplayImmediate;
    case DisplayRule::Switch:
      return abi::kDisplaySwitch;
    case DisplayRule::Blend:
      return abi::kDisplayBlend;
    case DisplayRule::Difference:
      return difference ? abi::kDisplayDifference : abi::kDisplayBlend;
  }
  return abi::kDisplayBlend;
}

// How many tiles around a judged tile hold pixels whose window reaches into it: show_display.comp
// shows them again with it. Immediate shows each pixel by itself.
uint32_t show_reach(uint32_t kernel_rule, uint32_t tile_size) {
  return kernel_rule == abi::kDisplayImmediate
             ? 0u
             : (abi::kDisplayWindowRadius + tile_size - 1u) / tile_size;
}

}  // namespace

ResolvePass::ResolvePass(const vk::Context& ctx, const GpuScene& scene, const TileState& tiles,
                         const Film& film, const GBufferPass& gbuffers, uint32_t width,
                         uint32_t height)
    : display(ctx, size_t(width) * height * sizeof(abi::DisplayTexel),
              VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      judgements(ctx, size_t(tiles.count()) * sizeof(abi::TileJudgement),
                 VK_BUFFER_USAGE_STORAGE_BUFFER_BIT),
      m_gbuffers(gbuffers),
      m_width(width),
      m_height(height),
      m_difference(film.keeps_difference()),
      m_tile_count(tiles.count()),
      m_tile_size(tiles.tile_size()),
      m_judge(ctx, "resolve_display.comp", {}, bindings(tiles, film, gbuffers),
              sizeof(abi::ResolvePush), &scene.descriptor_set()),
      m_show(ctx, "show_display.comp", {}, bindings(tiles, film, gbuffers),
             sizeof(abi::ResolvePush), &scene.descriptor_set()) {
  clear();
}

std::vector<vk::BufferBinding> ResolvePass::bindings(const TileState& tiles, const Film& film,
                                                     const GBufferPass& gbuffers) const {
  return {
      {abi::kResolveTileList, &tiles.schedule},  {abi::kResolveAccumulation, &film.accumulation},
      {abi::kResolveTileFlags, &tiles.flags},    {abi::kResolveDisplay, &display},
      {abi::kResolveGBuffer, &gbuffers.current}, {abi::kResolveDifference, &film.difference},
      {abi::kResolveJudgements, &judgements}};
}

void ResolvePass::clear() {
  abi::DisplayTexel black{};
  black.shownRecord = black.staleRecord = abi::kRecordUnknown;
  black.shownNormal = black.staleNormal = abi::kNormalUnknown;
  black.screenNoise = 1.0f;
  const std::vector<abi::DisplayTexel> texels(size_t(m_width) * m_height, black);
  display.upload(texels.data(), texels.size() * sizeof(abi::DisplayTexel));
  const std::vector<abi::TileJudgement> none(m_tile_count, abi::TileJudgement{});
  judgements.upload(none.data(), none.size() * sizeof(abi::TileJudgement));
}

void ResolvePass::record(VkCommandBuffer cmd, const Tiles& tiles, DisplayRule rule) const {
  record_pass(cmd, tiles, kernel_rule(rule, m_difference));
}

void ResolvePass::record_capture_stale(VkCommandBuffer cmd, uint32_t tile_count) const {
  record_pass(cmd, {abi::kInvalidIndex, tile_count}, abi::kDisplayCapture);
}

void ResolvePass::record_pass(VkCommandBuffer cmd, const Tiles& tiles, uint32_t rule) const {
  const abi::ResolvePush push{tiles.offset,
                              tiles.count,
                              tiles.require_flags,
                              tiles.skip_flags,
                              rule,
                              kSwitchThreshold,
                              m_gbuffers.is_current() ? 1u : 0u,
                              m_difference ? 1u : 0u,
                              next_epoch(),
                              show_reach(rule, m_tile_size)};
  vk::compute_to_compute_barrier(cmd);
  m_judge.dispatch(cmd, &push, tiles.count);
  if (rule == abi::kDisplayCapture) return;
  vk::compute_to_compute_barrier(cmd);
  const uint32_t side = 2u * push.showReach + 1u;  // workgroups per entry: the tiles around it
  m_show.dispatch(cmd, &push, tiles.count * side * side);
}

uint32_t ResolvePass::next_epoch() const {
  if (++m_epoch == 0) m_epoch = 1;  // 0 marks what the capture cleared
  return m_epoch;
}

ImageRGB ResolvePass::displayed_image() const {
  return image_of(m_width, m_height, display.download_all<abi::DisplayTexel>(),
                  [](const abi::DisplayTexel& t) { return t.shown; });
}

}  // namespace hipr
