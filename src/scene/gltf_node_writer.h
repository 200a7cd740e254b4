#pragma once
// Scene nodes and cameras -> glTF JSON: local transforms, KHR_node_visibility, and the camera
// node a camera edit adds to a scene that had none.
#include <string>

#include "hipr/scene.h"
#include "scene/gltf_json_values.h"

namespace hipr::gltf {

// Rewrites doc's nodes (and cameras) where `scene` differs from what they load as: a
// translation-only change of a TRS node keeps TRS form, any other change writes `matrix` (TRS
// for a node an animation targets, where glTF forbids a matrix); a hidden node gets
// KHR_node_visibility "visible": false. Nodes and cameras the scene has beyond the file's are
// appended (roots of the default scene) when they are in the scene; a file's node that a delete
// took out of the scene is unlisted from its parent's children (or the scene's nodes) and stays,
// unused. `name` names the file in messages.
void write_nodes(Json& doc, const Scene& scene, const std::string& name);

}  // namespace hipr::gltf
