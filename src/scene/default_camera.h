#pragma once
#include "hipr/scene.h"

namespace hipr {

// The camera to render from: the scene's first camera node, else Scene::default_camera, else
// (a scene built in code and never edited) the framing camera. Its frame keeps rotation and
// translation only.
Camera resolve_camera(const Scene& scene);

// The view of a scene without a camera node, as stored: Scene::default_camera, or the framing
// camera while none is stored. A camera node pinned from it renders the same bits.
Camera default_view(const Scene& scene);

// One that frames the bounding sphere of the scene's visible instances from +Z (looking down -Z).
Camera framing_camera(const Scene& scene);

// Decides the default camera once: stores framing_camera(scene) in a scene that has neither a
// camera node nor a stored default camera. The loader calls it, and so does every edit before it
// changes anything.
void fix_default_camera(Scene& scene);

}  // namespace hipr
