#include "card_scene.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "test_support.h"

namespace hipr::test {

Scene make_card_camera_scene(float env) {
  Scene scene;
  Node camera_node;
  camera_node.name = "camera";
  camera_node.camera = 0;
  camera_node.local = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, 3.0f));
  scene.nodes = {camera_node};
  scene.children = {{}};
  scene.root_nodes = {0};
  Camera camera;
  camera.yfov =
      2.0f * std::atan(1.0f / 3.0f);  // half-height 1 at distance 3: the card fills the view
  scene.cameras.push_back(camera);
  if (env > 0.0f) scene.environment = uniform_environment(env);
  return scene;
}

uint32_t add_card(Scene& scene, const std::string& name, const glm::mat4& transform,
                  const MaterialParameters& material) {
  MeshPrimitive card;
  card.positions = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}};
  card.normals.assign(4, glm::vec3(0, 0, 1));
  card.tangents.assign(4, glm::vec4(1, 0, 0, 1));
  for (const glm::vec3& p : card.positions) {
    card.uvs.push_back({(p.x + 1.0f) * 0.5f, (1.0f - p.y) * 0.5f});
    card.uvs1.push_back({1.0f - card.uvs.back().x, card.uvs.back().y});
  }
  card.indices = {0, 1, 2, 0, 2, 3};
  card.material = uint32_t(scene.materials.size());
  scene.materials.push_back({name, material});
  scene.meshes.push_back({name, {card}});
  Node node;
  node.name = name;
  node.mesh = int(scene.meshes.size() - 1);
  node.local = transform;
  scene.nodes.push_back(node);
  scene.children.push_back({});
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return card.material;
}

MaterialParameters black_material() {
  MaterialParameters m = default_material_params();
  m.base_color = glm::vec3(0.0f);
  m.specular_weight = 0.0f;
  return m;
}

MaterialParameters emissive_texture_material(uint32_t texture) {
  MaterialParameters m = black_material();
  m.emission_color = glm::vec3(1.0f);
  m.emission_luminance = 1.0f;
  m.emission_texture = texture;
  return m;
}

}  // namespace hipr::test
