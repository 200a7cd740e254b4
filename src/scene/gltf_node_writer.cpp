#include "scene/gltf_node_writer.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/gtx/matrix_decompose.hpp>

#include "core/error.h"
#include "scene/default_camera.h"
#include "scene/gltf_hipr_extras.h"
#include "scene/gltf_node_transform.h"

namespace hipr::gltf {
namespace {

constexpr const char* kVisibility = "KHR_node_visibility";

glm::mat4 loaded_transform(const Json& node) {
  return local_transform(json_numbers(node, "matrix"), json_numbers(node, "translation"),
                         json_numbers(node, "rotation"), json_numbers(node, "scale"));
}

Json numbers(const float* v, int count) {
  Json array = Json::array();
  for (int i = 0; i < count; ++i) array.push_back(json_number(v[i]));
  return array;
}

// glTF forbids `matrix` on a node an animation channel targets.
bool animated(const Json& doc, size_t node) {
  if (!doc.contains("animations") || !doc["animations"].is_array()) return false;
  for (const Json& animation : doc["animations"]) {
    if (!animation.is_object() || !animation.contains("channels") ||
        !animation["channels"].is_array())
      continue;
    for (const Json& channel : animation["channels"])
      if (channel.is_object() && channel.contains("target") && channel["target"].is_object() &&
          channel["target"].contains("node") && channel["target"]["node"].is_number_integer() &&
          channel["target"]["node"].get<int64_t>() == int64_t(node))
        return true;
  }
  return false;
}

void write_matrix(Json& node, const glm::mat4& m) {
  node.erase("translation");
  node.erase("rotation");
  node.erase("scale");
  node["matrix"] = numbers(glm::value_ptr(m), 16);
}

// An animated node must stay TRS: decompose (exact up to float rounding, which the round trip
// tolerates); a matrix that is no TRS at all is written as a matrix all the same.
void write_trs(Json& node, const glm::mat4& m) {
  glm::vec3 scale, translation, skew;
  glm::quat rotation;
  glm::vec4 perspective;
  if (!glm::decompose(m, scale, rotation, translation, skew, perspective)) {
    write_matrix(node, m);
    return;
  }
  node.erase("matrix");
  node["translation"] = numbers(glm::value_ptr(translation), 3);
  const float xyzw[4] = {rotation.x, rotation.y, rotation.z, rotation.w};
  node["rotation"] = numbers(xyzw, 4);
  node["scale"] = numbers(glm::value_ptr(scale), 3);
}

void write_transform(Json& node, const glm::mat4& loaded, const glm::mat4& wanted,
                     bool is_animated) {
  if (node.contains("matrix") && !is_animated) {
    write_matrix(node, wanted);
    return;
  }
  // Only the translation column moved: T * R * S keeps R * S to the bit, so write just T.
  bool translation_only = wanted[3][3] == loaded[3][3];
  for (int c = 0; c < 3; ++c) translation_only = translation_only && wanted[c] == loaded[c];
  if (translation_only && !node.contains("matrix")) {
    node["translation"] = numbers(glm::value_ptr(wanted[3]), 3);
  } else if (is_animated) {
    write_trs(node, wanted);
  } else {
    write_matrix(node, wanted);
  }
}

void write_visibility(Json& node, bool visible) {
  const bool loads_hidden = node.contains("extensions") && node["extensions"].is_object() &&
                            node["extensions"].contains(kVisibility) &&
                            node["extensions"][kVisibility].is_object() &&
                            node["extensions"][kVisibility].value("visible", true) == false;
  if (loads_hidden == !visible) return;
  edit_object(node, "extensions", [&](Json& extensions) {
    edit_object(extensions, kVisibility, [&](Json& ext) { ext["visible"] = visible; });
  });
}

// The thin lens, in extras (glTF cameras are pinholes): written while it is open.
void write_lens(Json& json, const Camera& camera) {
  erase_extra(json, kLensExtras);
  if (camera.aperture_radius > 0.0f)
    set_extra(json, kLensExtras,
              {{"aperture_radius", json_number(camera.aperture_radius)},
               {"focus_distance", json_number(camera.focus_distance)}},
              "camera " + camera.name);
}

Json new_camera(const Camera& camera) {
  Json perspective = {{"yfov", json_number(camera.yfov)}, {"znear", json_number(camera.znear)}};
  Json out = Json::object();
  if (!camera.name.empty()) out["name"] = camera.name;
  out["type"] = "perspective";
  out["perspective"] = std::move(perspective);
  write_lens(out, camera);
  return out;
}

// A perspective camera's field of view and near plane, should the scene's differ; its lens.
void write_camera(Json& json, const Camera& camera) {
  if (json.is_object()) write_lens(json, camera);
  if (!json.is_object() || json.value("type", "") != "perspective")
    return;  // orthographic: loaded as a fixed fov
  edit_object(json, "perspective", [&](Json& p) {
    put_number(p, "yfov", camera.yfov, camera.yfov, camera.yfov);
    const bool near_loads = p.contains("znear") && p["znear"].is_number() &&
                            float(std::max(p["znear"].get<double>(), 0.0)) == camera.znear;
    if (!near_loads) p["znear"] = json_number(camera.znear);
  });
}

// The loader's default scene: "scene", else the first; none without scenes (every parentless
// node is a root then). A pointer into `doc`: adding a key to `doc` moves it.
Json* default_scene(Json& doc) {
  if (!doc.contains("scenes") || !doc["scenes"].is_array() || doc["scenes"].empty()) return nullptr;
  const size_t index =
      doc.contains("scene") && doc["scene"].is_number_integer() ? doc["scene"].get<size_t>() : 0;
  return index < doc["scenes"].size() ? &doc["scenes"][index] : nullptr;
}

Json new_node(const Node& node) {
  Json out = Json::object();
  out["name"] = node.name;
  if (node.mesh >= 0) out["mesh"] = node.mesh;
  if (node.camera >= 0) out["camera"] = node.camera;
  if (node.light >= 0) out["extensions"]["KHR_lights_punctual"]["light"] = node.light;
  out["matrix"] = numbers(glm::value_ptr(node.local), 16);
  if (!node.visible) out["extensions"][kVisibility]["visible"] = false;
  return out;
}

}  // namespace

void write_nodes(Json& doc, const Scene& scene, const std::string& name) {
  const size_t node_count = array_length(doc, "nodes"), camera_count = array_length(doc, "cameras");
  if (scene.nodes.size() < node_count || scene.cameras.size() < camera_count)
    throw InputError(name +
                     ": the scene has fewer nodes or cameras than its file: the file changed since "
                     "it was loaded");

  for (size_t i = 0; i < camera_count; ++i) write_camera(doc["cameras"][i], scene.cameras[i]);
  for (size_t i = camera_count; i < scene.cameras.size(); ++i)
    doc["cameras"].push_back(new_camera(scene.cameras[i]));

  Json* roots = default_scene(doc);
  const auto unlist = [](Json& owner, const char* key, size_t node) {
    if (!owner.contains(key) || !owner[key].is_array()) return;
    Json& list = owner[key];
    for (size_t k = list.size(); k-- > 0;)
      if (list[k].is_number_integer() && list[k].get<size_t>() == node) list.erase(k);
    if (list.empty()) owner.erase(key);  // glTF wants these lists non-empty
  };
  const std::vector<bool> reachable = scene.reachable_nodes();
  for (size_t i = 0; i < node_count; ++i) {
    Json& node = doc["nodes"][i];
    const glm::mat4 loaded = loaded_transform(node);
    if (loaded != scene.nodes[i].local)
      write_transform(node, loaded, scene.nodes[i].local, animated(doc, i));
    write_visibility(node, scene.nodes[i].visible);
    // A deleted node: its parent (or the scene) no longer lists it; it stays in the file, unused.
    const int parent = scene.nodes[i].parent;
    const std::vector<uint32_t>& siblings =
        parent >= 0 ? scene.children[size_t(parent)] : scene.root_nodes;
    if (std::find(siblings.begin(), siblings.end(), uint32_t(i)) != siblings.end()) continue;
    if (parent >= 0)
      unlist(doc["nodes"][size_t(parent)], "children", i);
    else if (roots)
      unlist(*roots, "nodes", i);
  }
  // Nodes edits appended, but those no longer in the scene: numbered after the file's.
  std::vector<size_t> written(scene.nodes.size(), SIZE_MAX);
  for (size_t i = 0; i < node_count; ++i) written[i] = i;
  size_t next = node_count;
  // (EXT_mesh_gpu_instancing instances go back into their extension: write_gpu_instances.)
  for (size_t i = node_count; i < scene.nodes.size(); ++i)
    if (reachable[i] && !scene.nodes[i].gpu_instance) written[i] = next++;
  for (size_t i = node_count; i < scene.nodes.size(); ++i) {
    if (!reachable[i] || scene.nodes[i].gpu_instance) continue;
    doc["nodes"].push_back(new_node(scene.nodes[i]));
    const int parent = scene.nodes[i].parent;
    if (parent >= 0)
      doc["nodes"][written[size_t(parent)]]["children"].push_back(written[i]);
    else if (roots)
      (*roots)["nodes"].push_back(written[i]);
  }
  // No camera node: the view the scene was seen from becomes one, so the file reopens as it was
  // seen (framed around the edited objects, it would not). Where the edits left the framing as
  // it was, the file stays without one (an unedited save is the source's document).
  if (scene.camera_node() >= 0) return;
  const Camera camera = default_view(scene);
  const Camera framed = framing_camera(scene);
  if (camera.camera_to_world != framed.camera_to_world || camera.yfov != framed.yfov ||
      camera.znear != framed.znear) {
    Node node;
    node.name = "default_camera";
    node.local = camera.camera_to_world;
    node.camera = int(array_length(doc, "cameras"));
    doc["cameras"].push_back(new_camera(camera));
    doc["nodes"].push_back(new_node(node));
    if (Json* scene_roots = default_scene(doc))
      (*scene_roots)["nodes"].push_back(doc["nodes"].size() - 1);
  }
}

}  // namespace hipr::gltf
