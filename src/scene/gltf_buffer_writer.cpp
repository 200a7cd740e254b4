#include "scene/gltf_buffer_writer.h"

#include "scene/base64.h"

namespace hipr::gltf {

Json& BufferWriter::list(const char* key) {
  if (!m_doc.contains(key) || !m_doc[key].is_array()) m_doc[key] = Json::array();
  return m_doc[key];
}

size_t BufferWriter::buffer_index() {
  if (m_buffer == SIZE_MAX) {
    m_buffer = list("buffers").size();
    list("buffers").push_back(Json::object());  // filled by finish(), once the bytes are known
  }
  return m_buffer;
}

size_t BufferWriter::add_view(const void* bytes, size_t size, int target) {
  m_bytes.resize((m_bytes.size() + 3) / 4 * 4, 0);
  const size_t offset = m_bytes.size();
  m_bytes.resize(offset + size);
  if (size > 0) std::memcpy(m_bytes.data() + offset, bytes, size);
  Json view = {{"buffer", buffer_index()}, {"byteOffset", offset}, {"byteLength", size}};
  if (target) view["target"] = target;
  list("bufferViews").push_back(std::move(view));
  return list("bufferViews").size() - 1;
}

void BufferWriter::finish() {
  if (m_buffer == SIZE_MAX) return;
  m_doc["buffers"][m_buffer] = {{"byteLength", m_bytes.size()},
                                {"uri", "data:application/octet-stream;base64," + base64_encode(m_bytes)}};
}

}  // namespace hipr::gltf
