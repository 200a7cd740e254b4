#pragma once
// What the viewer's passes read of a renderer on the device, with no copy through the host:
// the display (DisplayPass shows it in place) and the debug overlays.
#include <cstdint>

#include "hipr/renderer.h"
#include "vk/buffer.h"

namespace hipr {

// The display (abi::DisplayTexel per pixel, `shown` is what the screen shows). Lives as long as
// the renderer.
const vk::Buffer& display_texels(const Renderer& renderer);

// The denoiser's result (a vec3 per pixel, DisplayPass::show_radiance), its pass made on the
// first call (compiled then where the renderer compiles kernels early). Lives as long as the
// renderer.
const vk::Buffer& denoised_display(Renderer& renderer);
// Records the denoiser over what the display shows now into that buffer, in the viewer's own
// frame: no submission of its own.
void record_denoise(Renderer& renderer, VkCommandBuffer cmd, const DenoiseSettings& settings);

// Whether the denoiser's pass and the exposure meter were made (a new renderer of the same
// window makes them again at once: Session::rebuild).
bool has_denoiser(const Renderer& renderer);
bool has_exposure_meter(const Renderer& renderer);

// The exposure in stops for what the display shows (image/auto_exposure.h's rule, to 1/16 of a
// stop), metered on the device: 4 KB read back, not the display.
float metered_display_exposure(Renderer& renderer);

// The viewer's overlays, made on the device into `output` (one RGBA8 word per pixel: the
// display pass's overlay buffer) from what the renderer holds there: object ids of the G-buffer,
// stage 2's tile weights, the tiles still owed a restart; and the outline of `selected_node` on
// top (UINT32_MAX: none). The G-buffer is used as it is: refresh it first where edits left it
// behind (policies without stage 1).
enum class DebugOverlay { None, Ids, TileWeights, OwedTiles };
void render_overlay(Renderer& renderer, DebugOverlay overlay, uint32_t selected_node,
                    const vk::Buffer& output);

}  // namespace hipr
