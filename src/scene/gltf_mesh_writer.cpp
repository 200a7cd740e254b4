#include "scene/gltf_mesh_writer.h"

#include <cstring>

#include "core/error.h"
#include "scene/base64.h"

namespace hipr::gltf {
namespace {

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

// The new buffer's bytes, and the views and accessors over them.
class AccessorWriter {
 public:
  AccessorWriter(Json& doc, size_t buffer) : m_doc(doc), m_buffer(buffer) {}

  template <typename T>
  size_t add(const std::vector<T>& values, int component_type, const char* type, int target) {
    const size_t offset = m_bytes.size();
    m_bytes.resize(offset + values.size() * sizeof(T));
    std::memcpy(m_bytes.data() + offset, values.data(), values.size() * sizeof(T));
    Json view = {{"buffer", m_buffer}, {"byteOffset", offset}, {"byteLength", values.size() * sizeof(T)},
                 {"target", target}};
    list("bufferViews").push_back(std::move(view));
    Json accessor = {{"bufferView", list("bufferViews").size() - 1},
                     {"componentType", component_type},
                     {"count", values.size() * sizeof(T) / element_size(type)},
                     {"type", type}};
    list("accessors").push_back(std::move(accessor));
    return list("accessors").size() - 1;
  }

  // POSITION needs its bounds.
  size_t add_positions(const std::vector<glm::vec3>& positions) {
    const size_t index = add(positions, kFloat, "VEC3", kArrayBuffer);
    glm::vec3 lo(0.0f), hi(0.0f);
    if (!positions.empty()) lo = hi = positions[0];
    for (const glm::vec3& p : positions) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    Json& accessor = list("accessors")[index];
    accessor["min"] = {json_number(lo.x), json_number(lo.y), json_number(lo.z)};
    accessor["max"] = {json_number(hi.x), json_number(hi.y), json_number(hi.z)};
    return index;
  }

  const std::vector<unsigned char>& bytes() const { return m_bytes; }

 private:
  static size_t element_size(const std::string& type) {
    return type == "SCALAR" ? 4 : type == "VEC2" ? 8 : type == "VEC3" ? 12 : 16;
  }
  Json& list(const char* key) {
    if (!m_doc.contains(key) || !m_doc[key].is_array()) m_doc[key] = Json::array();
    return m_doc[key];
  }

  Json& m_doc;
  size_t m_buffer;
  std::vector<unsigned char> m_bytes;
};

bool any_nonzero(const std::vector<glm::vec2>& uvs) {
  for (const glm::vec2& uv : uvs)
    if (uv != glm::vec2(0.0f)) return true;
  return false;
}

Json primitive_json(AccessorWriter& out, const MeshPrimitive& p, size_t file_materials) {
  Json attributes = Json::object();
  attributes["POSITION"] = out.add_positions(p.positions);
  if (p.normals.size() == p.positions.size()) attributes["NORMAL"] = out.add(p.normals, kFloat, "VEC3", kArrayBuffer);
  if (p.tangents.size() == p.positions.size()) attributes["TANGENT"] = out.add(p.tangents, kFloat, "VEC4", kArrayBuffer);
  if (p.uvs.size() == p.positions.size() && any_nonzero(p.uvs))
    attributes["TEXCOORD_0"] = out.add(p.uvs, kFloat, "VEC2", kArrayBuffer);
  if (p.uvs1.size() == p.positions.size() && any_nonzero(p.uvs1))
    attributes["TEXCOORD_1"] = out.add(p.uvs1, kFloat, "VEC2", kArrayBuffer);
  Json primitive = {{"attributes", std::move(attributes)},
                    {"indices", out.add(p.indices, kUnsignedInt, "SCALAR", kElementArrayBuffer)}};
  // The scene's materials: the file's, glTF's default (a primitive without one), then imported
  // ones, which write_new_materials appends to the file's.
  if (p.material < file_materials) primitive["material"] = p.material;
  else if (p.material > file_materials) primitive["material"] = p.material - 1;
  return primitive;
}

}  // namespace

void write_meshes(Json& doc, const Scene& scene, const std::string& name) {
  const size_t file_meshes = doc.contains("meshes") && doc["meshes"].is_array() ? doc["meshes"].size() : 0;
  const size_t file_materials = doc.contains("materials") && doc["materials"].is_array() ? doc["materials"].size() : 0;
  if (scene.loaded_mesh_revisions.size() != file_meshes || scene.meshes.size() < file_meshes)
    throw InputError(name + ": the scene has other meshes than its file: the file changed since it was loaded");
  std::vector<size_t> deformed;
  for (size_t m = 0; m < file_meshes; ++m)
    if (scene.meshes[m].revision != scene.loaded_mesh_revisions[m] && !scene.meshes[m].primitives.empty())
      deformed.push_back(m);
  if (deformed.empty() && scene.meshes.size() == file_meshes) return;

  if (!doc.contains("buffers") || !doc["buffers"].is_array()) doc["buffers"] = Json::array();
  const size_t buffer = doc["buffers"].size();
  doc["buffers"].push_back(Json::object());  // filled below, once its bytes are known
  AccessorWriter out(doc, buffer);
  const auto primitives_of = [&](const Mesh& mesh) {
    Json primitives = Json::array();
    for (const MeshPrimitive& p : mesh.primitives) primitives.push_back(primitive_json(out, p, file_materials));
    return primitives;
  };
  for (size_t m : deformed) {
    Json& mesh = doc["meshes"][m];
    mesh["primitives"] = primitives_of(scene.meshes[m]);
    mesh.erase("weights");  // the morph targets went with the old primitives
  }
  // Imported meshes, appended in the scene's order: their indices stay the scene's.
  if (!doc.contains("meshes") || !doc["meshes"].is_array()) doc["meshes"] = Json::array();
  for (size_t m = file_meshes; m < scene.meshes.size(); ++m) {
    Json mesh = {{"name", scene.meshes[m].name}, {"primitives", primitives_of(scene.meshes[m])}};
    if (scene.meshes[m].primitives.empty())  // glTF wants a primitive: one triangle of nothing
      mesh["primitives"] = primitives_of(Mesh{"", {MeshPrimitive{{glm::vec3(0.0f)}, {}, {}, {}, {}, {0, 0, 0}, 0}}, 0});
    doc["meshes"].push_back(std::move(mesh));
  }
  doc["buffers"][buffer] = {{"byteLength", out.bytes().size()},
                            {"uri", "data:application/octet-stream;base64," + base64_encode(out.bytes())}};
}

}  // namespace hipr::gltf
