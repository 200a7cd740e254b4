#include "render/display_pass.h"

#include <cmath>

#include "core/error.h"
#include "shaders/shared/bindings/display.h"

namespace hipr {
namespace {

vk::Buffer storage(const vk::Context& ctx, size_t bytes) {
  return vk::Buffer(ctx, bytes, VK_BUFFER_USAGE_STORAGE_BUFFER_BIT);
}

constexpr uint32_t kTexelStride = sizeof(abi::DisplayTexel) / sizeof(float);
constexpr uint32_t kRadianceStride = 3;

}  // namespace

DisplayPass::DisplayPass(const vk::Context& ctx, uint32_t width, uint32_t height)
    : m_ctx(ctx),
      m_width(width),
      m_height(height),
      m_texels(storage(ctx, size_t(width) * height * sizeof(abi::DisplayTexel))),
      m_overlay(storage(ctx, size_t(width) * height * 4)),
      // The output follows the window's size: bound when record() makes it.
      m_pipeline(ctx, "display.comp", {},
                 {{abi::kDisplayTexels, &m_texels},
                  {abi::kDisplayOverlay, &m_overlay},
                  {abi::kDisplayOutput, nullptr}},
                 sizeof(abi::DisplayPush)),
      m_stride(kTexelStride) {
  m_texels.clear();
  m_overlay.clear();
}

void DisplayPass::show(const vk::Buffer& display_texels) {
  if (display_texels.size() < size_t(m_width) * m_height * sizeof(abi::DisplayTexel))
    throw InternalError("the display buffer is smaller than the rendered size");
  m_pipeline.bind_buffer(abi::kDisplayTexels, display_texels);
  m_stride = kTexelStride;
}

void DisplayPass::show_radiance(const vk::Buffer& rgb) {
  if (rgb.size() < size_t(m_width) * m_height * kRadianceStride * sizeof(float))
    throw InternalError("the radiance buffer is smaller than the rendered size");
  m_pipeline.bind_buffer(abi::kDisplayTexels, rgb);
  m_stride = kRadianceStride;
}

void DisplayPass::set_image(const ImageRGB& image) {
  if (image.width != m_width || image.height != m_height ||
      image.rgb.size() != size_t(m_width) * m_height * 3)
    throw InternalError("the displayed image does not have the rendered size");
  std::vector<abi::DisplayTexel> texels(size_t(m_width) * m_height, abi::DisplayTexel{});
  for (size_t i = 0; i < texels.size(); ++i)
    texels[i].shown = glm::vec3(image.rgb[3 * i], image.rgb[3 * i + 1], image.rgb[3 * i + 2]);
  m_texels.upload(texels.data(), texels.size() * sizeof(abi::DisplayTexel));
  m_pipeline.bind_buffer(abi::kDisplayTexels, m_texels);
  m_stride = kTexelStride;
}

void DisplayPass::set_overlay(const std::vector<uint32_t>& rgba8) {
  if (rgba8.size() != size_t(m_width) * m_height)
    throw InternalError("the overlay does not have the rendered size");
  m_overlay.upload(rgba8.data(), rgba8.size() * 4);
}

void DisplayPass::record(VkCommandBuffer cmd, const DisplayView& view) {
  const size_t pixels = size_t(view.output_width) * view.output_height;
  if (pixels == 0 || !(view.scale > 0.0f)) throw InternalError("empty display view");
  if (!m_output || m_output.size() != pixels * 4) {
    m_output = storage(m_ctx, pixels * 4);
    m_pipeline.bind_buffer(abi::kDisplayOutput, m_output);
  }
  abi::DisplayPush push{};
  push.outputWidth = view.output_width;
  push.outputHeight = view.output_height;
  push.sourceWidth = m_width;
  push.sourceHeight = m_height;
  push.viewX = view.x;
  push.viewY = view.y;
  push.viewScale = view.scale;
  push.exposureScale = std::exp2(view.exposure_ev);
  push.background = view.background;
  push.overlayEnabled = view.overlay ? 1u : 0u;
  push.toneMapper = uint32_t(view.tone_mapper);
  push.sourceStride = m_stride;
  // The display and the overlay were written by earlier submissions (kernels, uploads).
  vk::transfer_to_compute_barrier(cmd);
  vk::compute_to_compute_barrier(cmd);
  m_pipeline.dispatch(cmd, &push,
                      uint32_t((pixels + abi::kWorkgroupSize - 1) / abi::kWorkgroupSize));
}

std::vector<uint32_t> DisplayPass::run(const DisplayView& view) {
  m_ctx.submit_and_wait([&](VkCommandBuffer cmd) { record(cmd, view); });
  return m_output.download_all<uint32_t>();
}

}  // namespace hipr
