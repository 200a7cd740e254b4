#pragma once
// The per-pixel state of a render (accumulation, display, light-group shares, difference
// records, the display's judgements; in the GPU's layout), to start several runs from one state:
// hipr bench runs every policy from the same converged render.
#include <cstdint>
#include <vector>

#include "hipr/renderer.h"

namespace hipr {

struct RenderSnapshot {
  std::vector<uint8_t> accumulation;
  std::vector<uint8_t> display;
  std::vector<uint8_t> light_groups;  // the accumulation's and the stale estimate's group shares
  std::vector<uint8_t> difference;    // the difference records
  std::vector<uint8_t> judgements;    // the display's per-tile judgements (TileJudgement)
};

RenderSnapshot snapshot_render(const Renderer& renderer);
// Throws InternalError for a snapshot of another image size.
void restore_render(Renderer& renderer, const RenderSnapshot& snapshot);

}  // namespace hipr
