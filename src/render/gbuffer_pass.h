#pragma once
// The G-buffer (visibility.comp): one ray through every pixel centre records which surface
// (GeometryRecord) the pixel sees, at what camera-space depth and the triangle's geometric
// normal (which face of it). The display resolve reads it (which surface a pixel shows), picking
// reads it, and HiPR's stage 1 compares it with the previous one, kept in `previous`.
#include <cstdint>
#include <memory>

#include "render/gpu_scene.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"

namespace hipr {

class GBufferPass {
 public:
  GBufferPass(const vk::Context& ctx, const GpuScene& scene, uint32_t width, uint32_t height);

  // Records the visibility pass into `current` (its kernel is made on first use: renders that
  // never ask which surface a pixel shows never compile it).
  void record(VkCommandBuffer cmd);
  // Records a copy of `current` into `previous`, before `current` is rendered anew.
  void record_keep_previous(VkCommandBuffer cmd) const;
  // Renders `current` now and waits.
  void render();

  // Whether `current` shows the scene as it is now (no scene change since it was rendered).
  bool is_current() const { return m_current; }
  void set_stale() { m_current = false; }
  // Whether `current` was ever rendered (what it holds before that is undefined).
  bool ever_rendered() const { return m_visibility != nullptr; }

  struct Hit {
    uint32_t record = UINT32_MAX;  // GeometryRecord, UINT32_MAX for background
    float depth = 0.0f;
  };
  Hit at(uint32_t x, uint32_t y) const;  // one texel read back

  vk::Buffer current, previous;  // GBufferTexel per pixel

 private:
  const vk::Context& m_ctx;
  const GpuScene& m_scene;
  uint32_t m_width, m_height;
  bool m_current = false;
  std::unique_ptr<vk::ComputePipeline> m_visibility;
};

}  // namespace hipr
