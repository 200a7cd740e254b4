#pragma once
// EXT_mesh_gpu_instancing back into glTF: the instance nodes the loader made (Node::gpu_instance)
// are not nodes of the file; their transforms go back into the extension of the node carrying
// them, rewritten only when they differ from what was loaded.
#include "hipr/scene.h"
#include "scene/gltf_buffer_writer.h"
#include "scene/gltf_json_values.h"

namespace hipr::gltf {

// For each node carrying instances: the instances still in the scene and visible, in order, as
// TRANSLATION, ROTATION and SCALE accessors (a hidden or deleted instance is left out; other
// attributes the file had per instance are dropped when the count changed). A node left with no
// instance shows nothing: its mesh and extension are removed.
void write_gpu_instances(Json& doc, const Scene& scene, BufferWriter& buffer);

}  // namespace hipr::gltf
