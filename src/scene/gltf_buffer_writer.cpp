#include "scene/gltf_buffer_writer.h"

#include "scene/base64.h"

namespace hipr::gltf {

size_t BufferWriter::buffer_index() {
  if (m_buffer == SIZE_MAX) {
    m_buffer = append_to(m_doc, "buffers",
                         Json::object());  // filled by finish(), once the bytes are known
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
  return append_to(m_doc, "bufferViews", std::move(view));
}

void BufferWriter::finish() {
  if (m_buffer == SIZE_MAX) return;
  m_doc["buffers"][m_buffer] = {
      {"byteLength", m_bytes.size()},
      {"uri", "data:application/octet-stream;base64," + base64_encode(m_bytes)}};
}

}  // namespace hipr::gltf
