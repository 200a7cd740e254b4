#include "app/viewer/view_layout.h"

#include <algorithm>
#include <cmath>

namespace hipr::viewer {

std::optional<glm::uvec2> ViewLayout::to_render(glm::vec2 window) const {
  const float rx = std::floor((window.x - float(x)) / scale);
  const float ry = std::floor((window.y - float(y)) / scale);
  if (rx < 0.0f || ry < 0.0f || rx >= float(render_width) || ry >= float(render_height))
    return std::nullopt;
  return glm::uvec2(uint32_t(rx), uint32_t(ry));
}

ViewLayout fit_view(uint32_t render_width, uint32_t render_height, uint32_t area_width,
                    uint32_t area_height) {
  ViewLayout layout;
  layout.render_width = render_width;
  layout.render_height = render_height;
  if (render_width == 0 || render_height == 0 || area_width == 0 || area_height == 0) return layout;
  float scale =
      std::min(float(area_width) / float(render_width), float(area_height) / float(render_height));
  if (scale >= 1.0f) scale = std::floor(scale);
  layout.scale = scale;
  layout.x = int(std::floor((float(area_width) - scale * float(render_width)) * 0.5f));
  layout.y = int(std::floor((float(area_height) - scale * float(render_height)) * 0.5f));
  return layout;
}

}  // namespace hipr::viewer
