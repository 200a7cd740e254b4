#include "scene/gltf_accessors.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "core/error.h"

namespace hipr::gltf {
namespace {

int component_size(int type) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_BYTE:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return 1;
    case TINYGLTF_COMPONENT_TYPE_SHORT:
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT:
      return 2;
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT:
    case TINYGLTF_COMPONENT_TYPE_FLOAT:
      return 4;
    default:
      return 0;
  }
}

// Where the accessor's elements live, after checking every element fits in its buffer.
struct ElementLayout {
  const unsigned char* base = nullptr;  // null: no bufferView, all zeros
  size_t stride = 0;
  size_t count = 0;
  int components = 0;
  int component_type = 0;
  bool normalized = false;
};

void check_buffer_view(const tinygltf::Model& model, int index, const std::string& what) {
  if (index < 0 || size_t(index) >= model.bufferViews.size())
    throw InputError(what + ": references missing bufferView " + std::to_string(index));
  const tinygltf::BufferView& view = model.bufferViews[size_t(index)];
  if (view.buffer < 0 || size_t(view.buffer) >= model.buffers.size())
    throw InputError(what + ": bufferView " + std::to_string(index) +
                     " references a missing buffer");
  const size_t size = model.buffers[size_t(view.buffer)].data.size();
  if (view.byteOffset > size || view.byteLength > size - view.byteOffset)
    throw InputError(what + ": bufferView " + std::to_string(index) +
                     " runs past the end of its buffer");
}

ElementLayout layout_of(const tinygltf::Model& model, int index, const std::string& what,
                        bool allow_sparse = false) {
  const auto fail = [&](const std::string& why) { throw InputError(what + ": " + why); };
  if (index < 0 || size_t(index) >= model.accessors.size())
    fail("accessor " + std::to_string(index) + " does not exist");
  const tinygltf::Accessor& accessor = model.accessors[size_t(index)];
  if (accessor.sparse.isSparse) {
    if (!allow_sparse) fail("sparse accessor " + std::to_string(index) + " is not supported");
    const auto& sparse = accessor.sparse;
    check_buffer_view(model, sparse.indices.bufferView, what + " sparse indices");
    check_buffer_view(model, sparse.values.bufferView, what + " sparse values");
    if (sparse.count < 0 || size_t(sparse.count) > accessor.count)
      fail("sparse accessor " + std::to_string(index) + " replaces more elements than it has");
    // Each array within its bufferView, checked without a product that could wrap.
    const auto fits = [&](int view_index, size_t offset, size_t element_bytes) {
      const size_t length = model.bufferViews[size_t(view_index)].byteLength;
      return element_bytes > 0 && offset <= length &&
             size_t(sparse.count) <= (length - offset) / element_bytes;
    };
    const size_t value_bytes =
        size_t(component_size(accessor.componentType)) * size_t(component_count(accessor.type));
    if (!fits(sparse.indices.bufferView, sparse.indices.byteOffset,
              size_t(component_size(sparse.indices.componentType))) ||
        !fits(sparse.values.bufferView, sparse.values.byteOffset, value_bytes))
      fail("sparse accessor " + std::to_string(index) + " runs past the end of its bufferViews");
  }
  ElementLayout layout;
  layout.count = accessor.count;
  layout.components = component_count(accessor.type);
  layout.component_type = accessor.componentType;
  layout.normalized = accessor.normalized;
  const int size = component_size(accessor.componentType);
  if (!layout.components || !size)
    fail("accessor " + std::to_string(index) + " has an invalid type");
  const size_t element_size = size_t(size) * size_t(layout.components);
  if (accessor.bufferView < 0) {  // all zeros, per the glTF spec: bounded apart (no bytes back it)
    if (layout.count > kMaxZeroFilledElements)
      fail("accessor " + std::to_string(index) + " has no bufferView and " +
           std::to_string(layout.count) + " elements (at most " +
           std::to_string(kMaxZeroFilledElements) + " without data)");
    return layout;
  }

  check_buffer_view(model, accessor.bufferView, what + ": accessor " + std::to_string(index));
  const tinygltf::BufferView& view = model.bufferViews[size_t(accessor.bufferView)];
  const tinygltf::Buffer& buffer = model.buffers[size_t(view.buffer)];
  layout.stride = view.byteStride ? view.byteStride : element_size;
  if (layout.stride < element_size) fail("bufferView stride is smaller than an element");
  // Checked step by step so no sum can wrap around (a hostile byteOffset near 2^64 would).
  const bool fits =
      accessor.byteOffset <= view.byteLength &&
      element_size <= view.byteLength - accessor.byteOffset &&
      (layout.count == 0 ||
       layout.count - 1 <= (view.byteLength - accessor.byteOffset - element_size) / layout.stride);
  if (!fits) fail("accessor " + std::to_string(index) + " runs past the end of its bufferView");
  layout.base = buffer.data.data() + view.byteOffset + accessor.byteOffset;
  return layout;
}

float read_component(const unsigned char* p, int type, bool normalized) {
  switch (type) {
    case TINYGLTF_COMPONENT_TYPE_FLOAT: {
      float v;
      std::memcpy(&v, p, 4);
      return v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE:
      return normalized ? *p / 255.0f : float(*p);
    case TINYGLTF_COMPONENT_TYPE_BYTE: {
      const float v = float(int8_t(*p));
      return normalized ? std::max(v / 127.0f, -1.0f) : v;
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT: {
      uint16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? v / 65535.0f : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_SHORT: {
      int16_t v;
      std::memcpy(&v, p, 2);
      return normalized ? std::max(v / 32767.0f, -1.0f) : float(v);
    }
    case TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT: {
      uint32_t v;
      std::memcpy(&v, p, 4);
      return float(v);
    }
    default:
      return 0.0f;
  }
}

}  // namespace

int component_count(int type) {
  switch (type) {
    case TINYGLTF_TYPE_SCALAR:
      return 1;
    case TINYGLTF_TYPE_VEC2:
      return 2;
    case TINYGLTF_TYPE_VEC3:
      return 3;
    case TINYGLTF_TYPE_VEC4:
      return 4;
    case TINYGLTF_TYPE_MAT2:
      return 4;
    case TINYGLTF_TYPE_MAT3:
      return 9;
    case TINYGLTF_TYPE_MAT4:
      return 16;
    default:
      return 0;
  }
}

namespace {

size_t primitive_elements(const tinygltf::Model& model, const tinygltf::Primitive& primitive) {
  const auto count = [&](int index) -> size_t {
    return index >= 0 && size_t(index) < model.accessors.size()
               ? model.accessors[size_t(index)].count
               : 0;
  };
  const auto position = primitive.attributes.find("POSITION");
  const size_t vertices = position == primitive.attributes.end() ? 0 : count(position->second);
  const size_t indices = primitive.indices >= 0 ? count(primitive.indices) : vertices;
  // Strips and fans: up to three list indices per index (points and lines make none).
  const size_t factor = primitive.mode == TINYGLTF_MODE_TRIANGLES || primitive.mode < 0 ? 1 : 3;
  if (indices > SIZE_MAX / 8 || vertices > SIZE_MAX / 8) return SIZE_MAX;
  return vertices + indices * factor;
}

}  // namespace

void check_scene_elements(const tinygltf::Model& model, const std::string& name) {
  size_t total = 0;
  for (const tinygltf::Mesh& mesh : model.meshes)
    for (const tinygltf::Primitive& primitive : mesh.primitives) {
      const int mode = primitive.mode < 0 ? TINYGLTF_MODE_TRIANGLES : primitive.mode;
      if (mode != TINYGLTF_MODE_TRIANGLES && mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
          mode != TINYGLTF_MODE_TRIANGLE_FAN)
        continue;  // skipped by the loader
      // Clamped so that the sum cannot wrap: it stops as soon as it passes the limit.
      total += std::min(primitive_elements(model, primitive), kMaxSceneElements + 1);
      if (total > kMaxSceneElements)
        throw InputError(name + ": more than " + std::to_string(kMaxSceneElements) +
                         " vertices and indices in all (hipr's limit for one scene)");
    }
}

void validate_all_accessors(const tinygltf::Model& model, const std::string& name) {
  for (size_t i = 0; i < model.bufferViews.size(); ++i) check_buffer_view(model, int(i), name);
  for (size_t i = 0; i < model.accessors.size(); ++i) layout_of(model, int(i), name, true);
}

std::vector<float> read_floats(const tinygltf::Model& model, int accessor, int components,
                               const std::string& what) {
  const ElementLayout layout = layout_of(model, accessor, what, true);
  if (layout.components != components)
    throw InputError(what + ": accessor " + std::to_string(accessor) + " has " +
                     std::to_string(layout.components) + " components, expected " +
                     std::to_string(components));
  std::vector<float> values(layout.count * size_t(components), 0.0f);
  const size_t component_bytes = size_t(component_size(layout.component_type));
  const auto read_element = [&](const unsigned char* element, size_t i) {
    for (int c = 0; c < components; ++c) {
      const float v = read_component(element + size_t(c) * component_bytes, layout.component_type,
                                     layout.normalized);
      if (!std::isfinite(v))
        throw InputError(what + ": accessor " + std::to_string(accessor) +
                         " holds a non-finite value");
      values[i * size_t(components) + size_t(c)] = v;
    }
  };
  if (layout.base)
    for (size_t i = 0; i < layout.count; ++i) read_element(layout.base + i * layout.stride, i);
  // Sparse: the listed elements replaced (bounds checked by layout_of; indices checked here).
  const tinygltf::Accessor& source = model.accessors[size_t(accessor)];
  if (source.sparse.isSparse) {
    const auto& sparse = source.sparse;
    const auto at = [&](int view, int offset) {
      const tinygltf::BufferView& v = model.bufferViews[size_t(view)];
      return model.buffers[size_t(v.buffer)].data.data() + v.byteOffset + size_t(offset);
    };
    const unsigned char* indices = at(sparse.indices.bufferView, sparse.indices.byteOffset);
    const unsigned char* replacements = at(sparse.values.bufferView, sparse.values.byteOffset);
    const int index_type = sparse.indices.componentType;
    const size_t index_bytes = size_t(component_size(index_type));
    if (index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
        index_type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
      throw InputError(what + ": sparse accessor " + std::to_string(accessor) +
                       " has indices of a non-integer type");
    for (size_t k = 0; k < size_t(sparse.count); ++k) {
      uint32_t index = 0;
      std::memcpy(&index, indices + k * index_bytes, index_bytes);  // little-endian
      if (index >= layout.count)
        throw InputError(what + ": sparse accessor " + std::to_string(accessor) +
                         " replaces element " + std::to_string(index) + " of " +
                         std::to_string(layout.count));
      read_element(replacements + k * component_bytes * size_t(components), index);
    }
  }
  return values;
}

std::vector<uint32_t> read_indices(const tinygltf::Model& model, int accessor,
                                   const std::string& what) {
  const ElementLayout layout = layout_of(model, accessor, what);
  if (layout.components != 1) throw InputError(what + ": index accessor is not SCALAR");
  const int type = layout.component_type;
  if (type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT &&
      type != TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT)
    throw InputError(what + ": index accessor has a non-integer type");
  std::vector<uint32_t> indices(layout.count, 0);
  if (!layout.base) return indices;
  for (size_t i = 0; i < layout.count; ++i) {
    const unsigned char* p = layout.base + i * layout.stride;
    uint32_t v = 0;
    if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE)
      v = *p;
    else if (type == TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) {
      uint16_t s;
      std::memcpy(&s, p, 2);
      v = s;
    } else
      std::memcpy(&v, p, 4);
    indices[i] = v;
  }
  return indices;
}

std::vector<glm::vec2> to_vec2(const std::vector<float>& v) {
  std::vector<glm::vec2> out(v.size() / 2);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {v[2 * i], v[2 * i + 1]};
  return out;
}

std::vector<glm::vec3> to_vec3(const std::vector<float>& v) {
  std::vector<glm::vec3> out(v.size() / 3);
  for (size_t i = 0; i < out.size(); ++i) out[i] = {v[3 * i], v[3 * i + 1], v[3 * i + 2]};
  return out;
}

std::vector<glm::vec4> to_vec4(const std::vector<float>& v) {
  std::vector<glm::vec4> out(v.size() / 4);
  for (size_t i = 0; i < out.size(); ++i)
    out[i] = {v[4 * i], v[4 * i + 1], v[4 * i + 2], v[4 * i + 3]};
  return out;
}

}  // namespace hipr::gltf
