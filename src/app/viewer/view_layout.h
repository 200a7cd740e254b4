#pragma once
// Where the rendered image sits in the window: centred in the view area (the window minus the
// side panel), at an integer zoom when it fits (crisp pixels), else scaled down to fit. The
// display pass draws with it and picking maps the mouse back through it.
#include <cstdint>
#include <glm/glm.hpp>
#include <optional>

namespace hipr::viewer {

struct ViewLayout {
  uint32_t render_width = 0;
  uint32_t render_height = 0;
  int x = 0;  // window pixel of the image's top-left corner
  int y = 0;
  float scale = 1.0f;  // window pixels per rendered pixel

  // The rendered pixel under a window pixel position (framebuffer coordinates), if any.
  std::optional<glm::uvec2> to_render(glm::vec2 window) const;
};

// `area_width` x `area_height`: the view area, starting at the window's left edge.
ViewLayout fit_view(uint32_t render_width, uint32_t render_height, uint32_t area_width,
                    uint32_t area_height);

}  // namespace hipr::viewer
