#include "render/denoise_pass.h"

#include <algorithm>

#include "shaders/shared/bindings/denoise.h"

namespace hipr {
namespace {

constexpr VkBufferUsageFlags kStorage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;

size_t pixels(uint32_t width, uint32_t height) { return size_t(width) * height; }

}  // namespace

DenoisePass::DenoisePass(const vk::Context& ctx, const GpuScene& scene, const Film& film,
                         const vk::Buffer& display, uint32_t width, uint32_t height)
    : result(ctx, pixels(width, height) * sizeof(abi::vec3), kStorage),
      m_ctx(ctx),
      m_width(width),
      m_height(height),
      m_guides(ctx, pixels(width, height) * sizeof(abi::DenoiseGuide), kStorage),
      m_geometry(ctx, pixels(width, height) * 2 * sizeof(uint32_t), kStorage),
      m_keys(ctx, pixels(width, height) * sizeof(uint32_t), kStorage),
      m_samples(ctx, pixels(width, height) * sizeof(uint32_t), kStorage),
      m_variance(ctx, pixels(width, height) * sizeof(abi::vec2), kStorage),
      m_ping(ctx, pixels(width, height) * sizeof(abi::vec4), kStorage),
      m_pong(ctx, pixels(width, height) * sizeof(abi::vec4), kStorage),
      m_frame(ctx, pixels(width, height) * sizeof(abi::vec3), kStorage),
      m_history(ctx, pixels(width, height) * 2 * sizeof(uint32_t), kStorage),
      m_shown_noise(ctx, pixels(width, height) * 6 * sizeof(uint32_t),
                    kStorage | VK_BUFFER_USAGE_TRANSFER_DST_BIT),
      m_trace_guides(ctx, "denoise_guides.comp", {},
                     {{abi::kDenoiseGuides, &m_guides}, {abi::kDenoiseGeometry, &m_geometry}}, 0,
                     &scene.descriptor_set()),
      m_keys_pass(ctx, "denoise_keys.comp", {},
                  {{abi::kDenoiseGuides, &m_guides},
                   {abi::kDenoiseDisplay, &display},
                   {abi::kDenoiseKeys, &m_keys}},
                  sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_prepare(ctx, "denoise_prepare.comp", {},
                {{abi::kDenoiseGuides, &m_guides},
                 {abi::kDenoiseDisplay, &display},
                 {abi::kDenoiseAccumulation, &film.accumulation},
                 {abi::kDenoiseKeys, &m_keys},
                 {abi::kDenoiseInput, &m_ping},
                 {abi::kDenoiseSamples, &m_samples},
                 {abi::kDenoiseVariance, &m_variance},
                 {abi::kDenoiseShownNoise, &m_shown_noise}},
                sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_ping_to_pong(ctx, "denoise_atrous.comp", {}, atrous_bindings(m_ping, m_pong),
                     sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_pong_to_ping(ctx, "denoise_atrous.comp", {}, atrous_bindings(m_pong, m_ping),
                     sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_blend_ping(ctx, "denoise_blend.comp", {}, blend_bindings(display, m_ping),
                   sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_blend_pong(ctx, "denoise_blend.comp", {}, blend_bindings(display, m_pong),
                   sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_temporal(ctx, "denoise_temporal.comp", {},
                 {{abi::kDenoiseKeys, &m_keys},
                  {abi::kDenoiseSamples, &m_samples},
                  {abi::kDenoiseVariance, &m_variance},
                  {abi::kDenoiseFrame, &m_frame},
                  {abi::kDenoiseResult, &result},
                  {abi::kDenoiseHistory, &m_history}},
                 sizeof(abi::DenoisePush), &scene.descriptor_set()),
      m_stopwatch(ctx, kMarks) {}

std::vector<vk::BufferBinding> DenoisePass::atrous_bindings(const vk::Buffer& input,
                                                            const vk::Buffer& output) const {
  return {{abi::kDenoiseGuides, &m_guides}, {abi::kDenoiseGeometry, &m_geometry},
          {abi::kDenoiseKeys, &m_keys},     {abi::kDenoiseSamples, &m_samples},
          {abi::kDenoiseInput, &input},     {abi::kDenoiseOutput, &output}};
}

std::vector<vk::BufferBinding> DenoisePass::blend_bindings(const vk::Buffer& display,
                                                           const vk::Buffer& filtered) const {
  return {{abi::kDenoiseGuides, &m_guides},     {abi::kDenoiseKeys, &m_keys},
          {abi::kDenoiseDisplay, &display},     {abi::kDenoiseInput, &filtered},
          {abi::kDenoiseVariance, &m_variance}, {abi::kDenoiseSamples, &m_samples},
          {abi::kDenoiseFrame, &m_frame}};
}

void DenoisePass::record(VkCommandBuffer cmd, const DenoiseSettings& settings) {
  record(cmd, settings, nullptr);
}

void DenoisePass::record(VkCommandBuffer cmd, const DenoiseSettings& settings,
                         const vk::GpuStopwatch* watch) {
  const auto mark = [&](Mark m) {
    if (watch) watch->mark(cmd, m);
  };
  const uint32_t groups = groups_for(m_width * m_height);
  if (watch) watch->reset(cmd);
  if (!m_shown_noise_cleared) {
    vkCmdFillBuffer(cmd, m_shown_noise.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::transfer_to_compute_barrier(cmd);
    m_shown_noise_cleared = true;
  }
  vk::compute_to_compute_barrier(cmd);
  mark(kStart);
  // What the last frame showed is of another scene, view or filter: nothing of it is kept.
  const bool history_reset = !m_guides_current || m_last_settings != settings;
  m_last_settings = settings;
  if (!m_guides_current) {
    m_trace_guides.dispatch(cmd, nullptr, groups);
    vk::compute_to_compute_barrier(cmd);
    m_guides_current = true;
  }
  mark(kGuidesDone);
  abi::DenoisePush push{};
  push.width = m_width;
  push.height = m_height;
  push.strength = settings.enabled ? std::max(settings.strength, 0.0f) : 0.0f;
  push.displayState = settings.display_state ? 1u : 0u;
  push.historyReset = history_reset ? 1u : 0u;
  push.historyKeep = std::clamp(settings.history, 0.0f, kMaxDenoiseHistory);
  m_keys_pass.dispatch(cmd, &push, groups);
  vk::compute_to_compute_barrier(cmd);
  m_prepare.dispatch(cmd, &push, groups);
  mark(kPrepareDone);
  const uint32_t passes = std::clamp(settings.passes, 1u, kMaxDenoisePasses);
  for (uint32_t pass = 0; pass < passes; ++pass) {
    vk::compute_to_compute_barrier(cmd);
    push.step = 1u << pass;
    (pass % 2 == 0 ? m_ping_to_pong : m_pong_to_ping).dispatch(cmd, &push, groups);
  }
  mark(kAtrousDone);
  vk::compute_to_compute_barrier(cmd);
  const uint32_t tiles = groups_for(m_width, abi::kDenoiseBlendTileWidth) *
                         groups_for(m_height, abi::kDenoiseBlendTileHeight);
  (passes % 2 == 0 ? m_blend_ping : m_blend_pong).dispatch(cmd, &push, tiles);
  mark(kBlendDone);
  vk::compute_to_compute_barrier(cmd);
  m_temporal.dispatch(cmd, &push, groups);
  mark(kTemporalDone);
}

std::optional<DenoiseGpuSeconds> DenoisePass::run(const DenoiseSettings& settings) {
  const bool traces_guides = !m_guides_current;
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) { record(cmd, settings, &m_stopwatch); });
  const auto at = m_stopwatch.read();
  if (!at) return std::nullopt;
  const std::vector<double>& t = *at;
  // Without guides to trace, the time between the first two marks is the queue's, not a kernel's.
  const double guides = traces_guides ? t[kGuidesDone] - t[kStart] : 0.0;
  return DenoiseGpuSeconds{.guides = guides,
                           .prepare = t[kPrepareDone] - t[kStart] - guides,
                           .atrous = t[kAtrousDone] - t[kPrepareDone],
                           .blend = t[kBlendDone] - t[kAtrousDone],
                           .temporal = t[kTemporalDone] - t[kBlendDone]};
}

ImageRGB DenoisePass::result_image() const {
  return image_of(m_width, m_height, result.download_all<abi::vec3>(),
                  [](const abi::vec3& v) { return v; });
}

}  // namespace hipr
