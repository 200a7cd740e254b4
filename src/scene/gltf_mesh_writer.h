#pragma once
// Scene meshes -> glTF JSON, for the meshes whose vertices edits changed (deform): their
// triangles, written again from the scene into a buffer of their own.
#include <string>

#include "hipr/scene.h"
#include "scene/gltf_buffer_writer.h"
#include "scene/gltf_json_values.h"

namespace hipr::gltf {

// Rewrites the primitives of every mesh of doc whose scene mesh is not as loaded (its revision
// differs from Scene::loaded_mesh_revisions), and appends the meshes the scene has beyond the
// file's (imported): positions, normals, tangents, texture coordinates and indices (a triangle
// list) as the scene holds them, into `out`, on the scene's materials as write_new_materials
// numbers them. Morph targets go
// (the deformed vertices replace what they morphed). Call before write_new_materials. `name`
// names the file in messages.
void write_meshes(Json& doc, const Scene& scene, BufferWriter& out, const std::string& name);

}  // namespace hipr::gltf
