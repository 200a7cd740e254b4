#pragma once
#include "hipr/scene.h"

namespace hipr {

// The camera to render from: the scene's first camera node, or one that frames the scene's
// bounding sphere from +Z (looking down -Z) when the scene has none.
Camera resolve_camera(const Scene& scene);

}  // namespace hipr
