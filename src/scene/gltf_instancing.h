#pragma once
// EXT_mesh_gpu_instancing as the loader reads it: the instances' transforms of one node.
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace hipr::gltf {

// T * R * S per instance from the extension's TRANSLATION, ROTATION (a quaternion, float or
// normalized) and SCALE accessors, any of which may be absent. Throws InputError naming `what`
// for missing or mismatched attributes or a zero quaternion.
std::vector<glm::mat4> gpu_instance_transforms(const tinygltf::Model& model,
                                               const tinygltf::Value& extension,
                                               const std::string& what);

}  // namespace hipr::gltf
