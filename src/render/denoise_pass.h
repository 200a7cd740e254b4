#pragma once
// The display denoiser (denoise_guides.comp, denoise_keys.comp, denoise_prepare.comp,
// denoise_atrous.comp, denoise_blend.comp, denoise_temporal.comp): an edge-avoiding a-trous filter
// of what the display shows, guided by each pixel's noise, the surface its centre sees and the
// scene state of its value, then steadied by the frame it showed last. It writes a copy (`result`):
// the accumulation and the display stay as they are (docs/method.md, "The denoised display").
#include <cstdint>
#include <optional>
#include <vector>

#include "hipr/denoise.h"
#include "hipr/image.h"
#include "render/film.h"
#include "render/gpu_scene.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/gpu_stopwatch.h"

namespace hipr {

class DenoisePass {
 public:
  DenoisePass(const vk::Context& ctx, const GpuScene& scene, const Film& film,
              const vk::Buffer& display, uint32_t width, uint32_t height);

  // The guides no longer show the scene (an edit, a camera move): the next record traces them,
  // and its frame keeps nothing of the last one.
  void set_guides_stale() { m_guides_current = false; }
  // Records the filter of what `display` shows now into `result` (after whatever the command
  // buffer wrote before): one frame, which keeps part of what the last record showed
  // (DenoiseSettings::history) unless something changed in between.
  void record(VkCommandBuffer cmd, const DenoiseSettings& settings);
  // Records, submits and waits; the device's time of each kernel where it has timestamps.
  std::optional<DenoiseGpuSeconds> run(const DenoiseSettings& settings);
  ImageRGB result_image() const;

  vk::Buffer result;  // vec3 per pixel: the denoised radiance

 private:
  // Marks of the stopwatch: the start, then the end of each kernel's part (DenoiseGpuSeconds).
  enum Mark : uint32_t {
    kStart,
    kGuidesDone,
    kPrepareDone,
    kAtrousDone,
    kBlendDone,
    kTemporalDone,
    kMarks
  };
  void record(VkCommandBuffer cmd, const DenoiseSettings& settings, const vk::GpuStopwatch* watch);
  std::vector<vk::BufferBinding> atrous_bindings(const vk::Buffer& input,
                                                 const vk::Buffer& output) const;
  std::vector<vk::BufferBinding> blend_bindings(const vk::Buffer& display,
                                                const vk::Buffer& filtered) const;

  const vk::Context& m_ctx;
  uint32_t m_width, m_height;
  bool m_guides_current = false;
  bool m_shown_noise_cleared = false;  // m_shown_noise holds no value of another run's memory
  // The settings of the last frame recorded (none yet: its history is not there to keep).
  std::optional<DenoiseSettings> m_last_settings;
  vk::Buffer m_guides, m_geometry, m_keys, m_samples, m_variance, m_ping, m_pong, m_frame,
      m_history, m_shown_noise;
  vk::ComputePipeline m_trace_guides;  // denoise_guides.comp
  vk::ComputePipeline m_keys_pass;     // denoise_keys.comp: guides, display -> keys
  vk::ComputePipeline m_prepare;       // denoise_prepare.comp: display, keys -> ping
  vk::ComputePipeline m_ping_to_pong;  // denoise_atrous.comp
  vk::ComputePipeline m_pong_to_ping;
  vk::ComputePipeline m_blend_ping;  // denoise_blend.comp, after an even number of passes
  vk::ComputePipeline m_blend_pong;  // after an odd number
  vk::ComputePipeline m_temporal;    // denoise_temporal.comp: m_frame and the last result -> result
  vk::GpuStopwatch m_stopwatch;      // run() only: a viewer's frame records without it
};

}  // namespace hipr
