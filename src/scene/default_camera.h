#pragma once
#include <string>

#include "hipr/scene.h"

namespace hipr {

// The camera to render from: the scene's chosen (Scene::active_camera) or first camera node, else
// Scene::default_camera, else (a scene built in code and never edited) the framing camera. Its
// frame keeps rotation and translation only.
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

// A camera node by what --camera takes: its position in Scene::camera_nodes() (0-based digits),
// or the name of the node or of its glTF camera. Throws InputError naming the cameras there are.
uint32_t find_camera_node(const Scene& scene, const std::string& name_or_index);

// "name (glTF camera name)" or "#node" when the node has no name: how lists show a camera.
std::string camera_label(const Scene& scene, uint32_t node);

}  // namespace hipr
