#pragma once
// The viewer's overlays, as RGBA8 words per rendered pixel for the display pass (sRGB-encoded
// colour, alpha = how much it covers the image). Colours come from image/debug_images, so the
// window shows what `hipr replay` writes as debug images. The window's overlays are made on the
// GPU (shaders/overlay.comp, Renderer::render_overlay); these CPU versions of them are the
// reference that kernel is tested against (tests/viewer_test.cpp).
#include <cstdint>
#include <string>
#include <vector>

namespace hipr::viewer {

enum class Overlay {
  None,
  Ids,      // object ids from the G-buffer, opaque (the paper's teaser, left)
  Weights,  // stage-2 tile weights as a heat map, active tiles blue (HiPR policy)
  Owed,     // tiles whose pixels still show radiance from before the last edit
};

Overlay parse_overlay(const std::string& name);  // ids, weights, owed, none; throws InputError
std::string overlay_name(Overlay overlay);

// Geometry of the rendered image and its tiles.
struct OverlayGrid {
  uint32_t width = 0;
  uint32_t height = 0;
  uint32_t tile_size = 16;
  uint32_t tiles_x = 0;
};

// `ids`: instance per pixel (UINT32_MAX: background).
std::vector<uint32_t> id_overlay(const std::vector<uint32_t>& ids, const OverlayGrid& grid);
// `weights`, `flags`: per tile (Renderer::tile_weights, tile_flags).
std::vector<uint32_t> weight_overlay(const std::vector<double>& weights,
                                     const std::vector<uint32_t>& flags, const OverlayGrid& grid);
// `owed`: per tile, pixels still owing a restart (Renderer::owed_tiles).
std::vector<uint32_t> owed_overlay(const std::vector<uint32_t>& owed, const OverlayGrid& grid);
// Draws the outline of `instance` (its pixels next to any other) over `overlay`.
void outline_instance(std::vector<uint32_t>& overlay, const std::vector<uint32_t>& ids,
                      uint32_t instance, const OverlayGrid& grid);

// Packs an sRGB-encoded colour in [0, 1] and a coverage in [0, 1] (R in the low byte).
uint32_t pack_rgba8(float r, float g, float b, float a);

}  // namespace hipr::viewer
