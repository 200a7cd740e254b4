#pragma once
// Read-backs of a render for inspection: what tests, debug images (hipr replay) and the
// benchmark look at, and a program that renders with the library does not need (the public
// Renderer keeps that). Each downloads from the device and waits.
#include <cstdint>
#include <vector>

#include "hipr/renderer.h"
#include "render/difference_records.h"

namespace hipr {

std::vector<uint32_t> read_tile_flags(const Renderer& renderer);  // abi::kTile* per tile
std::vector<double> read_tile_weights(const Renderer& renderer);  // stage 2's W(T) per tile
std::vector<uint32_t> read_schedule(const Renderer& renderer);    // tile ids, in order
// Per tile: how many of its pixels still show radiance from before the last edit (they owe a
// restart at their next visit).
std::vector<uint32_t> read_owed_tiles(const Renderer& renderer);
// The G-buffer of the scene as it is (rendered first where it is not).
std::vector<abi::GBufferTexel> read_gbuffer(Renderer& renderer);
// What the screen shows per pixel, with the values and samples behind it (the display rules').
std::vector<abi::DisplayTexel> read_display(const Renderer& renderer);
// The difference estimates of the samples since the last edit (empty without
// RenderSettings::difference_estimate).
DifferenceEstimates read_difference_estimates(const Renderer& renderer);

}  // namespace hipr
