#include "scene/gltf_mesh_writer.h"

#include "core/error.h"

namespace hipr::gltf {
namespace {

constexpr int kFloat = 5126, kUnsignedInt = 5125;
constexpr int kArrayBuffer = 34962, kElementArrayBuffer = 34963;

bool any_nonzero(const std::vector<glm::vec2>& uvs) {
  for (const glm::vec2& uv : uvs)
    if (uv != glm::vec2(0.0f)) return true;
  return false;
}

Json primitive_json(Json& doc, BufferWriter& out, const MeshPrimitive& p, size_t file_materials) {
  Json attributes = Json::object();
  attributes["POSITION"] = out.add_accessor(p.positions, kFloat, "VEC3", kArrayBuffer);
  // POSITION needs its bounds.
  glm::vec3 lo(0.0f), hi(0.0f);
  if (!p.positions.empty()) lo = hi = p.positions[0];
  for (const glm::vec3& v : p.positions) {
    lo = glm::min(lo, v);
    hi = glm::max(hi, v);
  }
  Json& accessor = doc["accessors"][attributes["POSITION"].get<size_t>()];
  accessor["min"] = {json_number(lo.x), json_number(lo.y), json_number(lo.z)};
  accessor["max"] = {json_number(hi.x), json_number(hi.y), json_number(hi.z)};
  if (p.normals.size() == p.positions.size())
    attributes["NORMAL"] = out.add_accessor(p.normals, kFloat, "VEC3", kArrayBuffer);
  if (p.tangents.size() == p.positions.size())
    attributes["TANGENT"] = out.add_accessor(p.tangents, kFloat, "VEC4", kArrayBuffer);
  if (p.uvs.size() == p.positions.size() && any_nonzero(p.uvs))
    attributes["TEXCOORD_0"] = out.add_accessor(p.uvs, kFloat, "VEC2", kArrayBuffer);
  if (p.uvs1.size() == p.positions.size() && any_nonzero(p.uvs1))
    attributes["TEXCOORD_1"] = out.add_accessor(p.uvs1, kFloat, "VEC2", kArrayBuffer);
  Json primitive = {
      {"attributes", std::move(attributes)},
      {"indices", out.add_accessor(p.indices, kUnsignedInt, "SCALAR", kElementArrayBuffer)}};
  // The scene's materials: the file's, glTF's default (a primitive without one), then imported
  // ones, which write_new_materials appends to the file's.
  if (p.material < file_materials)
    primitive["material"] = p.material;
  else if (p.material > file_materials)
    primitive["material"] = p.material - 1;
  return primitive;
}

}  // namespace

void write_meshes(Json& doc, const Scene& scene, BufferWriter& out, const std::string& name) {
  const size_t file_meshes = array_length(doc, "meshes"),
               file_materials = array_length(doc, "materials");
  if (scene.loaded_mesh_revisions.size() != file_meshes || scene.meshes.size() < file_meshes)
    throw InputError(
        name + ": the scene has other meshes than its file: the file changed since it was loaded");
  std::vector<size_t> deformed;
  for (size_t m = 0; m < file_meshes; ++m)
    if (scene.meshes[m].revision != scene.loaded_mesh_revisions[m] &&
        !scene.meshes[m].primitives.empty())
      deformed.push_back(m);
  if (deformed.empty() && scene.meshes.size() == file_meshes) return;

  const auto primitives_of = [&](const Mesh& mesh) {
    Json primitives = Json::array();
    for (const MeshPrimitive& p : mesh.primitives)
      primitives.push_back(primitive_json(doc, out, p, file_materials));
    return primitives;
  };
  for (size_t m : deformed) {
    Json& mesh = doc["meshes"][m];
    mesh["primitives"] = primitives_of(scene.meshes[m]);
    mesh.erase("weights");  // the morph targets went with the old primitives
  }
  // Imported meshes, appended in the scene's order: their indices stay the scene's.
  // (No reference into doc is held across writing: a new top-level key may move the others.)
  for (size_t m = file_meshes; m < scene.meshes.size(); ++m) {
    Json mesh = {{"name", scene.meshes[m].name}, {"primitives", primitives_of(scene.meshes[m])}};
    if (scene.meshes[m].primitives.empty())  // glTF wants a primitive: one triangle of nothing
      mesh["primitives"] = primitives_of(
          Mesh{"", {MeshPrimitive{{glm::vec3(0.0f)}, {}, {}, {}, {}, {0, 0, 0}, 0}}, 0});
    append_to(doc, "meshes", std::move(mesh));
  }
}

}  // namespace hipr::gltf
