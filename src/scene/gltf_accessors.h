#pragma once
// Bounds-checked reads of glTF accessors. Every offset, stride and count is validated against
// the buffer before a byte is read, so a hostile file cannot cause an out-of-bounds access.
#include <tiny_gltf.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace hipr::gltf {

// Limits on what a file's counts may make the loader allocate, checked before it allocates
// (README, "Limits"). An accessor without a bufferView is all zeros: its count costs memory
// without costing file bytes, so it is bounded on its own.
inline constexpr size_t kMaxZeroFilledElements = size_t(1) << 22;
// Vertices plus indices (after strips and fans become triangles) over all the file's primitives:
// about 40 million triangles. Primitives may share an accessor, so counts add up beyond the file.
inline constexpr size_t kMaxSceneElements = size_t(1) << 27;
// Decoded images: a side, one image's pixels, and all images' pixels (RGBA8: 1 GiB).
inline constexpr int kMaxImageSide = 16384;
inline constexpr size_t kMaxImagePixels = size_t(1) << 26;
inline constexpr size_t kMaxScenePixels = size_t(1) << 28;

// Components per element of an accessor type (TINYGLTF_TYPE_*): 1 to 16; 0 for an unknown type.
int component_count(int type);

// Throws InputError when the file's triangle primitives add up to more than kMaxSceneElements
// vertices and indices, counted from their accessors before any is read.
void check_scene_elements(const tinygltf::Model& model, const std::string& name);

// Reads a float vector accessor (VEC2/VEC3/VEC4, SCALAR or MAT4), converting normalized integers
// and applying its sparse substitutions.
// `components` is what the caller wants; the accessor must have exactly that many.
std::vector<float> read_floats(const tinygltf::Model& model, int accessor, int components,
                               const std::string& what);

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int accessor,
                                   const std::string& what);

// Checks every bufferView and accessor in the file, used or not (a file with broken data is
// refused as a whole, as the glTF validator does). Throws InputError naming the first problem.
void validate_all_accessors(const tinygltf::Model& model, const std::string& name);

std::vector<glm::vec2> to_vec2(const std::vector<float>& values);
std::vector<glm::vec3> to_vec3(const std::vector<float>& values);
std::vector<glm::vec4> to_vec4(const std::vector<float>& values);

}  // namespace hipr::gltf
