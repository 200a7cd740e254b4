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

// What the display shows now, denoised by `settings` into the denoiser's result (a vec3 per
// pixel, DisplayPass::show_radiance), on the device; waits. Lives as long as the renderer.
const vk::Buffer& denoised_display(Renderer& renderer, const DenoiseSettings& settings);

// The viewer's overlays, made on the device into `output` (one RGBA8 word per pixel: the
// display pass's overlay buffer) from what the renderer holds there: object ids of the G-buffer,
// stage 2's tile weights, the tiles still owed a restart; and the outline of `selected_node` on
// top (UINT32_MAX: none). The G-buffer is used as it is: refresh it first where edits left it
// behind (policies without stage 1).
enum class DebugOverlay { None, Ids, TileWeights, OwedTiles };
void render_overlay(Renderer& renderer, DebugOverlay overlay, uint32_t selected_node,
                    const vk::Buffer& output);

}  // namespace hipr
