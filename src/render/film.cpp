#include "render/film.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "shaders/shared/bindings/film.h"

namespace hipr {
namespace {

vk::Buffer storage(const vk::Context& ctx, size_t bytes) {
  return vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

}  // namespace

uint32_t groups_for(uint32_t items, uint32_t group_size) {
  return (items + group_size - 1) / group_size;
}

Film::Film(const vk::Context& ctx, uint32_t width, uint32_t height, uint32_t light_groups,
           bool keep_difference, const vk::DescriptorSet& scene, const vk::Buffer& tile_flags)
    : accumulation(storage(ctx, size_t(width) * height * sizeof(abi::PixelAccum))),
      // Read after every step (the scheduler's work, convergence): mapped where the device allows.
      stats(ctx, sizeof(abi::RenderStats), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT,
            vk::MemoryUse::Shared),
      group_sums(storage(
          ctx, std::max<size_t>(size_t(width) * height * light_groups, 1) * sizeof(glm::vec3))),
      difference(storage(
          ctx, (keep_difference ? size_t(width) * height : 1) * sizeof(abi::DifferenceRecord))),
      m_ctx(ctx),
      m_width(width),
      m_height(height),
      m_light_groups(light_groups),
      m_difference(keep_difference),
      m_mark_owed(ctx, "mark_owed.comp", {},
                  {{abi::kOwedAccumulation, &accumulation}, {abi::kOwedTileFlags, &tile_flags}}, 0,
                  &scene),
      // The kernel's 64-bit atomics land in device memory (mapped where the device allows), not
      // in host memory across the bus.
      m_total(ctx, sizeof(uint64_t), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Shared),
      m_sum_samples(ctx, "sum_samples.comp", {},
                    {{abi::kSumAccumulation, &accumulation}, {abi::kSumTotal, &m_total}},
                    sizeof(uint32_t)),
      m_noise_partials(ctx, size_t(groups_for(width * height)) * sizeof(abi::NoisePartial),
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryUse::Shared),
      m_film_noise(
          ctx, "film_noise.comp", {},
          {{abi::kNoiseAccumulation, &accumulation}, {abi::kNoisePartials, &m_noise_partials}},
          sizeof(uint32_t)) {
  clear();
}

void Film::record_mark_all_owed(VkCommandBuffer cmd) const {
  m_mark_owed.dispatch(cmd, nullptr, groups_for(m_width * m_height));
}

ImageRGB Film::image() const {
  return image_of(m_width, m_height, accumulation.download_all<abi::PixelAccum>(),
                  [](const abi::PixelAccum& a) {
                    const uint32_t count = a.count & abi::kPixelCountMask;
                    return count ? a.sum * (1.0f / float(count)) : glm::vec3(0.0f);
                  });
}

ImageRGB Film::group_image(uint32_t group) const {
  if (group >= m_light_groups) throw InternalError("no light group " + std::to_string(group));
  const auto accum = accumulation.download_all<abi::PixelAccum>();
  const auto sums = group_sums.download_all<glm::vec3>();
  std::vector<glm::vec3> mean(accum.size(), glm::vec3(0.0f));
  for (size_t i = 0; i < accum.size(); ++i) {
    const uint32_t count = accum[i].count & abi::kPixelCountMask;
    if (count) mean[i] = sums[i * m_light_groups + group] * (1.0f / float(count));
  }
  return image_of(m_width, m_height, mean, [](const glm::vec3& v) { return v; });
}

std::vector<uint32_t> Film::sample_counts() const {
  const auto accum = accumulation.download_all<abi::PixelAccum>();
  std::vector<uint32_t> counts(accum.size());
  for (size_t i = 0; i < accum.size(); ++i) counts[i] = accum[i].count & abi::kPixelCountMask;
  return counts;
}

uint64_t Film::total_samples() const {
  const uint32_t pixels = m_width * m_height;
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) {
    vkCmdFillBuffer(cmd, m_total.handle(), 0, VK_WHOLE_SIZE, 0);
    vk::transfer_to_compute_barrier(cmd);
    m_sum_samples.dispatch(cmd, &pixels, groups_for(pixels));
  });
  uint64_t total = 0;
  m_total.download(&total, sizeof total);
  return total;
}

FilmNoise Film::noise() const {
  const uint32_t pixels = m_width * m_height;
  m_ctx.submit_and_wait(
      [&](VkCommandBuffer cmd) { m_film_noise.dispatch(cmd, &pixels, groups_for(pixels)); });
  FilmNoise noise;
  noise.pixels = pixels;
  double sum = 0.0;
  for (const abi::NoisePartial& partial : m_noise_partials.download_all<abi::NoisePartial>()) {
    sum += double(partial.relmse);
    noise.unknown_pixels += partial.unknown;
  }
  const uint64_t known = noise.pixels - noise.unknown_pixels;
  // relmse() averages over channels as well as pixels.
  noise.relmse = known ? sum / (3.0 * double(known)) : 0.0;
  return noise;
}

std::vector<bool> Film::owed_pixels() const {
  const auto accum = accumulation.download_all<abi::PixelAccum>();
  std::vector<bool> owed(accum.size());
  for (size_t i = 0; i < accum.size(); ++i) owed[i] = (accum[i].count & abi::kPixelOwed) != 0;
  return owed;
}

RenderCounters Film::counters() const {
  abi::RenderStats s{};
  stats.download(&s, sizeof s);
  return {s.rays, s.samples, s.nonFiniteSamples, s.cameraRays, s.shadowRays, s.guideRays};
}

void Film::clear() {
  accumulation.clear();
  group_sums.clear();
  difference.clear();
  stats.clear();
}

}  // namespace hipr
