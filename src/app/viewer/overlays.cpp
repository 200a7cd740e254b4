#include "app/viewer/overlays.h"

#include <algorithm>
#include <cmath>

#include "core/error.h"
#include "image/debug_images.h"
#include "image/tonemap.h"

namespace hipr::viewer {
namespace {

// The heat map must stay readable over the picture, the owed tint must not hide it.
constexpr float kWeightCoverage = 0.7f;
constexpr float kOwedCoverage = 0.45f;

uint32_t byte(float v) { return uint32_t(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }

// A debug image (linear RGB) -> overlay words with one coverage.
std::vector<uint32_t> from_image(const ImageRGB& image, float coverage) {
  std::vector<uint32_t> out(size_t(image.width) * image.height);
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = pack_rgba8(srgb_encode(image.rgb[3 * i]), srgb_encode(image.rgb[3 * i + 1]),
                        srgb_encode(image.rgb[3 * i + 2]), coverage);
  return out;
}

}  // namespace

uint32_t pack_rgba8(float r, float g, float b, float a) {
  return byte(r) | byte(g) << 8 | byte(b) << 16 | byte(a) << 24;
}

Overlay parse_overlay(const std::string& name) {
  for (Overlay o : {Overlay::None, Overlay::Ids, Overlay::Weights, Overlay::Owed})
    if (overlay_name(o) == name) return o;
  throw InputError("unknown overlay '" + name + "' (none, ids, weights, owed)");
}

std::string overlay_name(Overlay overlay) {
  switch (overlay) {
    case Overlay::None:
      return "none";
    case Overlay::Ids:
      return "ids";
    case Overlay::Weights:
      return "weights";
    case Overlay::Owed:
      return "owed";
  }
  return "?";
}

std::vector<uint32_t> id_overlay(const std::vector<uint32_t>& ids, const OverlayGrid& grid) {
  return from_image(object_id_image(ids, grid.width, grid.height), 1.0f);
}

std::vector<uint32_t> weight_overlay(const std::vector<double>& weights,
                                     const std::vector<uint32_t>& flags, const OverlayGrid& grid) {
  return from_image(
      tile_weight_image(weights, flags, grid.tiles_x, grid.tile_size, grid.width, grid.height),
      kWeightCoverage);
}

std::vector<uint32_t> owed_overlay(const std::vector<uint32_t>& owed, const OverlayGrid& grid) {
  std::vector<uint32_t> out(size_t(grid.width) * grid.height, 0u);
  const uint32_t tint = pack_rgba8(0.95f, 0.1f, 0.75f, kOwedCoverage);
  for (uint32_t y = 0; y < grid.height; ++y)
    for (uint32_t x = 0; x < grid.width; ++x)
      if (owed[(y / grid.tile_size) * grid.tiles_x + x / grid.tile_size] > 0)
        out[size_t(y) * grid.width + x] = tint;
  return out;
}

void outline_instance(std::vector<uint32_t>& overlay, const std::vector<uint32_t>& ids,
                      uint32_t instance, const OverlayGrid& grid) {
  const uint32_t colour = pack_rgba8(1.0f, 0.6f, 0.1f, 1.0f);
  const auto id_at = [&](int64_t x, int64_t y) -> uint32_t {
    if (x < 0 || y < 0 || x >= int64_t(grid.width) || y >= int64_t(grid.height)) return UINT32_MAX;
    return ids[size_t(y) * grid.width + size_t(x)];
  };
  for (int64_t y = 0; y < int64_t(grid.height); ++y)
    for (int64_t x = 0; x < int64_t(grid.width); ++x) {
      if (id_at(x, y) != instance) continue;
      if (id_at(x - 1, y) != instance || id_at(x + 1, y) != instance ||
          id_at(x, y - 1) != instance || id_at(x, y + 1) != instance)
        overlay[size_t(y) * grid.width + size_t(x)] = colour;
    }
}

}  // namespace hipr::viewer
