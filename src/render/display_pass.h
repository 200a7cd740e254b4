#pragma once
// The viewer's display pass (shaders/display.comp): the displayed radiance, tone-mapped as
// tonemap_srgb8 does (exposure, tone mapper), with an overlay blended on top, becomes the RGBA8
// pixels of the window. It runs on the GPU so the window can be larger than the render (letterbox,
// nearest texel) without a CPU pass over every window pixel, and it reads the renderer's display
// buffer where the resolve wrote it (show()): no image crosses to the host and back per frame.
#include <cstdint>
#include <vector>

#include "image/image_io.h"
#include "image/tonemap.h"
#include "vk/buffer.h"
#include "vk/compute_pipeline.h"
#include "vk/context.h"

namespace hipr {

// Where and how the rendered image appears in the window.
struct DisplayView {
  uint32_t output_width = 0;  // window pixels
  uint32_t output_height = 0;
  int x = 0;  // top-left of the rendered image in the window
  int y = 0;
  float scale = 1.0f;  // window pixels per rendered pixel
  float exposure_ev = 0.0f;
  ToneMapper tone_mapper = ToneMapper::Clamp;
  uint32_t background = 0xff202020u;  // RGBA8 (R in the low byte)
  bool overlay = false;
};

class DisplayPass {
 public:
  // `width` x `height`: the rendered image's size.
  DisplayPass(const vk::Context& ctx, uint32_t width, uint32_t height);

  // Shows a renderer's display (abi::DisplayTexel per rendered pixel, Renderer::display_texels):
  // read at every record(), so what the resolve writes later shows without another call. The
  // buffer must outlive its use here (the viewer shows its session's renderer).
  void show(const vk::Buffer& display_texels);
  // Shows linear RGB radiance instead (a vec3 per rendered pixel: the denoiser's result), read
  // in place the same way.
  void show_radiance(const vk::Buffer& rgb);
  // Shows an image instead (linear RGB, the rendered size; uploaded once: tests, screenshots).
  void set_image(const ImageRGB& image);
  // One RGBA8 word per rendered pixel: sRGB-encoded colour, alpha = how much it covers.
  void set_overlay(const std::vector<uint32_t>& rgba8);
  // The overlay's buffer, for a kernel to write in place (Renderer::render_overlay).
  const vk::Buffer& overlay_buffer() const { return m_overlay; }

  // Records the dispatch (resizing the output for the window first: call it only when no
  // submitted work still reads the output). output() then holds the window's pixels.
  void record(VkCommandBuffer cmd, const DisplayView& view);
  const vk::Buffer& output() const { return m_output; }

  // Records, submits, waits and reads the window pixels back (tests, no window needed).
  std::vector<uint32_t> run(const DisplayView& view);

 private:
  const vk::Context& m_ctx;
  uint32_t m_width, m_height;
  vk::Buffer m_texels, m_overlay, m_output;  // m_texels: set_image's, when no display is shown
  vk::ComputePipeline m_pipeline;
  uint32_t m_stride;  // floats per pixel of the buffer shown (DisplayPush::sourceStride)
};

}  // namespace hipr
