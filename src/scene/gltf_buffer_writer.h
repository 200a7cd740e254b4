#pragma once
// A buffer the writer adds to a glTF document for what it writes anew (deformed and imported
// meshes, imported images): views and accessors over it are appended as they come, and the
// buffer itself (a data: URI; write_glb moves it into the BIN chunk) once everything is in.
#include <cstddef>
#include <cstring>
#include <string>
#include <vector>

#include "scene/gltf_json_values.h"

namespace hipr::gltf {

class BufferWriter {
 public:
  explicit BufferWriter(Json& doc) : m_doc(doc) {}

  // A view over `bytes` (4-aligned); `target` 0 for none. Returns the view's index.
  size_t add_view(const void* bytes, size_t size, int target);
  // A view and an accessor over `values` (float or uint32 components). Returns the accessor.
  template <typename T>
  size_t add_accessor(const std::vector<T>& values, int component_type, const char* type,
                      int target) {
    const size_t view = add_view(values.data(), values.size() * sizeof(T), target);
    Json accessor = {{"bufferView", view},
                     {"componentType", component_type},
                     {"count", values.size() * sizeof(T) / element_size(type)},
                     {"type", type}};
    return append_to(m_doc, "accessors", std::move(accessor));
  }
  // Appends the buffer to the document, when anything went into it.
  void finish();

 private:
  static size_t element_size(const std::string& type) {
    return type == "SCALAR" ? 4 : type == "VEC2" ? 8 : type == "VEC3" ? 12 : 16;
  }
  size_t buffer_index();

  Json& m_doc;
  std::vector<unsigned char> m_bytes;
  size_t m_buffer = SIZE_MAX;  // its index, once a view needs it
};

}  // namespace hipr::gltf
