// Geometry edits on the scene model. Node indices are stable: whatever an edit adds goes at the
// end of its list, a delete detaches, and undo restores the structure saved before the edit.
#include "scene/geometry_edits.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/hash.h"
#include "hipr/scene_loader.h"
#include "scene/default_camera.h"

namespace hipr {
namespace {

bool name_in_scene(const Scene& scene, const std::vector<bool>& reachable,
                   const std::string& name) {
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    if (reachable[n] && scene.nodes[n].name == name) return true;
  return false;
}

// The name a new node gets: `wanted`, refused when a node in the scene has it already (edits
// then could not tell them apart), or, when empty, `base` or else "<base>.1", "<base>.2"...
// whichever is free.
std::string new_node_name(const Scene& scene, const std::string& wanted, std::string base) {
  const std::vector<bool> reachable = scene.reachable_nodes();
  if (!wanted.empty()) {
    if (wanted[0] == '#')
      throw InputError("a new node's name may not start with '#' ('" + wanted + "')");
    if (name_in_scene(scene, reachable, wanted))
      throw InputError("a node named '" + wanted + "' is in the scene already");
    return wanted;
  }
  if (base.empty()) base = "node";
  if (!name_in_scene(scene, reachable, base)) return base;
  for (size_t k = 1;; ++k) {
    std::string candidate = base + "." + std::to_string(k);
    if (!name_in_scene(scene, reachable, candidate)) return candidate;
  }
}

void attach(Scene& scene, uint32_t node) {
  const int parent = scene.nodes[node].parent;
  (parent >= 0 ? scene.children[size_t(parent)] : scene.root_nodes).push_back(node);
}

void detach(Scene& scene, uint32_t node) {
  const int parent = scene.nodes[node].parent;
  std::vector<uint32_t>& list = parent >= 0 ? scene.children[size_t(parent)] : scene.root_nodes;
  list.erase(std::remove(list.begin(), list.end(), node), list.end());
}

// Copies `source` and its subtree under `parent`; returns the copy's index.
uint32_t copy_subtree(Scene& scene, uint32_t source, int parent, const std::string& name) {
  Node copy = scene.nodes[source];
  copy.name = name;
  copy.parent = parent;
  copy.gpu_instance = false;  // a node of its own (saved as one), not an instance of the file's
  if (copy.light >= 0) {      // a lamp of its own: editing one leaves the other
    scene.lights.push_back(scene.lights[size_t(copy.light)]);
    copy.light = int(scene.lights.size() - 1);
  }
  const uint32_t index = uint32_t(scene.nodes.size());
  scene.nodes.push_back(std::move(copy));
  scene.children.emplace_back();
  const std::vector<uint32_t> kids = scene.children[source];  // copied: the list may move
  const std::string prefix = name + "/";
  for (uint32_t kid : kids) copy_subtree(scene, kid, int(index), prefix + scene.nodes[kid].name);
  attach(scene, index);
  return index;
}

// Drops, from the end of the lists, nodes that edits appended and that are no longer in the
// scene, and appended lights no node uses: a duplicate undone by a delete leaves nothing behind.
void drop_detached_tail(Scene& scene) {
  const std::vector<bool> reachable = scene.reachable_nodes();
  while (scene.nodes.size() > scene.loaded_node_count && !reachable[scene.nodes.size() - 1]) {
    const uint32_t last = uint32_t(scene.nodes.size() - 1);
    detach(scene, last);
    for (uint32_t kid : scene.children[last]) scene.nodes[kid].parent = -1;  // detached with it
    scene.nodes.pop_back();
    scene.children.pop_back();
  }
  while (scene.lights.size() > scene.loaded_light_count) {
    const int last = int(scene.lights.size() - 1);
    if (std::any_of(scene.nodes.begin(), scene.nodes.end(),
                    [&](const Node& n) { return n.light == last; }))
      break;
    scene.lights.pop_back();
  }
}

// Appends `other` (a loaded file) to `scene` under a new root node; returns that node.
uint32_t append_scene(Scene& scene, Scene&& other, const std::string& name,
                      const glm::vec3& translate) {
  const uint32_t image_base = uint32_t(scene.images.size()),
                 texture_base = uint32_t(scene.textures.size());
  const uint32_t material_base = uint32_t(scene.materials.size()),
                 mesh_base = uint32_t(scene.meshes.size());
  const int light_base = int(scene.lights.size());
  for (Image& image : other.images) scene.images.push_back(std::move(image));
  for (Texture texture : other.textures) {
    texture.image += image_base;
    scene.textures.push_back(std::move(texture));
  }
  for (Material material : other.materials) {
    for (uint32_t* slot : texture_slots(material.params))
      if (*slot != kNoTexture) *slot += texture_base;
    scene.materials.push_back(std::move(material));
  }
  for (Mesh& mesh : other.meshes) {
    for (MeshPrimitive& primitive : mesh.primitives) {
      // An import brings its default materials; its variants are not the scene's.
      primitive.material = primitive.default_material + material_base;
      primitive.default_material = primitive.material;
      primitive.variant_materials.clear();
    }
    scene.meshes.push_back(std::move(mesh));
  }
  for (PunctualLight& light : other.lights) scene.lights.push_back(std::move(light));
  for (const std::string& extension : other.extensions_used)
    if (std::find(scene.extensions_used.begin(), scene.extensions_used.end(), extension) ==
        scene.extensions_used.end())
      scene.extensions_used.push_back(extension);

  Node root;
  root.name = name;
  root.local = glm::translate(glm::mat4(1.0f), translate);
  const uint32_t root_index = uint32_t(scene.nodes.size());
  scene.nodes.push_back(root);
  scene.children.emplace_back();
  scene.root_nodes.push_back(root_index);
  const uint32_t node_base = root_index + 1;
  for (size_t n = 0; n < other.nodes.size(); ++n) {
    Node node = std::move(other.nodes[n]);
    if (node.parent >= 0) node.parent += int(node_base);
    if (node.mesh >= 0) node.mesh += int(mesh_base);
    if (node.light >= 0) node.light += light_base;
    node.camera = -1;  // the scene keeps its own view
    scene.nodes.push_back(std::move(node));
    std::vector<uint32_t> kids = other.children[n];
    for (uint32_t& kid : kids) kid += node_base;
    scene.children.push_back(std::move(kids));
  }
  // The file's default scene hangs under the new root; its other parentless nodes stay out.
  for (uint32_t r : other.root_nodes) {
    scene.nodes[node_base + r].parent = int(root_index);
    scene.children[root_index].push_back(node_base + r);
  }
  return root_index;
}

void check_affine(const glm::mat4& m) {
  if (m[0][3] != 0.0f || m[1][3] != 0.0f || m[2][3] != 0.0f || m[3][3] != 1.0f)
    throw InputError("a deform matrix must be affine (its last row 0 0 0 1)");
  const float det = glm::determinant(glm::mat3(m));
  if (!std::isfinite(det) || std::abs(det) < 1e-12f)
    throw InputError("a deform matrix must be invertible");
}

glm::vec3 unit_or(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return length > 0.0f && std::isfinite(length) ? v / length : fallback;
}

void deform_mesh(Mesh& mesh, const glm::mat4& m) {
  const glm::mat3 linear(m);
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(linear));
  const bool mirrors = glm::determinant(linear) < 0.0f;
  for (MeshPrimitive& p : mesh.primitives) {
    for (glm::vec3& position : p.positions) position = glm::vec3(m * glm::vec4(position, 1.0f));
    for (glm::vec3& normal : p.normals) normal = unit_or(normal_matrix * normal, normal);
    for (glm::vec4& tangent : p.tangents) {
      const glm::vec3 t = unit_or(linear * glm::vec3(tangent), glm::vec3(tangent));
      tangent = glm::vec4(t, mirrors ? -tangent.w : tangent.w);
    }
    // A mirror turns the triangles inside out: swap two corners so they still face their normals.
    if (mirrors)
      for (size_t i = 0; i + 2 < p.indices.size(); i += 3)
        std::swap(p.indices[i + 1], p.indices[i + 2]);
  }
}

size_t mesh_of(const Scene& scene, const std::string& node_name) {
  const Node& node = scene.nodes[find_node(scene, node_name)];
  if (node.mesh < 0) throw InputError("node '" + node_name + "' has no mesh to deform");
  return size_t(node.mesh);
}

}  // namespace

size_t pin_default_camera(Scene& scene) {
  if (const int node = scene.camera_node(); node >= 0) return size_t(node);
  const Camera camera = default_view(scene);  // as stored: the pinned node renders the same bits
  scene.cameras.push_back(camera);
  Node camera_node;
  camera_node.name = "camera";
  camera_node.camera = int(scene.cameras.size() - 1);
  camera_node.local = camera.camera_to_world;
  scene.nodes.push_back(camera_node);
  scene.children.emplace_back();
  scene.root_nodes.push_back(uint32_t(scene.nodes.size() - 1));
  return scene.nodes.size() - 1;
}

void check_duplicate(const Scene& scene, const DuplicateEdit& edit) {
  const size_t source = find_node(scene, edit.node);
  new_node_name(scene, edit.as, scene.nodes[source].name);
}

void apply_duplicate(Scene& scene, const DuplicateEdit& edit) {
  const size_t source = find_node(scene, edit.node);
  const std::string name = new_node_name(scene, edit.as, scene.nodes[source].name);
  const uint32_t copy = copy_subtree(scene, uint32_t(source), scene.nodes[source].parent, name);
  scene.nodes[copy].local[3] += glm::vec4(edit.translate, 0.0f);
}

void apply_delete(Scene& scene, const DeleteEdit& edit) {
  const size_t node = find_node(scene, edit.node);
  detach(scene, uint32_t(node));
  drop_detached_tail(scene);
}

void apply_import(Scene& scene, const ImportEdit& edit) {
  Scene other = load_scene(edit.file);  // first: a bad file changes nothing
  const std::string name = new_node_name(scene, edit.as, edit.file.stem().string());
  // The scene's fingerprint (what cached references are keyed by) covers the imported bytes.
  scene.content_hash = Hasher().add(scene.content_hash).add(other.content_hash).hex();
  append_scene(scene, std::move(other), name, edit.translate);
}

void check_deform(const Scene& scene, const DeformEdit& edit) {
  mesh_of(scene, edit.node);
  if (!edit.restore) check_affine(edit.matrix);
}

void apply_deform(Scene& scene, const DeformEdit& edit) {
  const size_t mesh = mesh_of(scene, edit.node);
  if (edit.restore) {  // an undo
    if (edit.restore->primitives.size() != scene.meshes[mesh].primitives.size())
      throw InternalError("a deform's undo for another mesh");
    scene.meshes[mesh] = *edit.restore;  // its revision with it: the vertices are those again
    return;
  }
  check_affine(edit.matrix);
  deform_mesh(scene.meshes[mesh], edit.matrix);
  scene.meshes[mesh].revision = mesh_revision(scene.meshes[mesh]);
}

StructureEdit structure_undo(const Scene& scene) {
  auto structure = std::make_shared<SceneStructure>();
  structure->nodes = scene.nodes;
  structure->root_nodes = scene.root_nodes;
  structure->children = scene.children;
  structure->lights = scene.lights;
  structure->cameras = scene.cameras;
  structure->extensions_used = scene.extensions_used;
  structure->content_hash = scene.content_hash;
  structure->meshes = scene.meshes.size();
  structure->materials = scene.materials.size();
  structure->textures = scene.textures.size();
  structure->images = scene.images.size();
  return {std::move(structure)};
}

void apply_structure(Scene& scene, const StructureEdit& edit) {
  const SceneStructure& s = *edit.restore;
  if (s.meshes > scene.meshes.size() || s.materials > scene.materials.size() ||
      s.textures > scene.textures.size() || s.images > scene.images.size())
    throw InternalError("a structure to restore that has more than the scene");
  scene.nodes = s.nodes;
  scene.root_nodes = s.root_nodes;
  scene.children = s.children;
  scene.lights = s.lights;
  scene.cameras = s.cameras;
  scene.extensions_used = s.extensions_used;
  scene.content_hash = s.content_hash;
  scene.meshes.resize(s.meshes);
  scene.materials.resize(s.materials);
  scene.textures.resize(s.textures);
  scene.images.resize(s.images);
}

}  // namespace hipr
