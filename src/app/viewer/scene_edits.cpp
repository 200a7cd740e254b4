#include "app/viewer/scene_edits.h"

#include <cctype>
#include <filesystem>

#include "core/error.h"
#include "scene/default_camera.h"

namespace hipr::viewer {
namespace {

std::string index_reference(uint32_t index) { return "#" + std::to_string(index); }

template <typename Items, typename NameOf>
std::string reference(const Items& items, uint32_t index, NameOf name_of) {
  const std::string& name = name_of(items[index]);
  // The edit model resolves a name to its first holder; "#..." would read as an index.
  if (name.empty() || name[0] == '#') return index_reference(index);
  for (uint32_t i = 0; i < items.size(); ++i)
    if (name_of(items[i]) == name) return i == index ? name : index_reference(index);
  return index_reference(index);
}

}  // namespace

std::string node_reference(const Scene& scene, uint32_t node) {
  return reference(scene.nodes, node, [](const Node& n) -> const std::string& { return n.name; });
}

std::string material_reference(const Scene& scene, uint32_t material) {
  return reference(scene.materials, material,
                   [](const Material& m) -> const std::string& { return m.name; });
}

std::string node_label(const Scene& scene, uint32_t node) {
  return scene.nodes[node].name.empty() ? index_reference(node) : scene.nodes[node].name;
}

bool try_edit(Session& session, ViewerState& state, const Edit& edit) {
  try {
    session.edit(edit);
    return true;
  } catch (const InputError& e) {
    state.error(e.what());
    return false;
  }
}

std::optional<uint32_t> selected_node(const Session& session, ViewerState& state) {
  const Scene& scene = session.scene();
  if (state.selected_node >= 0 && size_t(state.selected_node) < scene.nodes.size() &&
      scene.reachable_nodes()[size_t(state.selected_node)])
    return uint32_t(state.selected_node);
  state.selected_node = -1;
  return std::nullopt;
}

void duplicate_selection(Session& session, ViewerState& state) {
  const std::optional<uint32_t> node = selected_node(session, state);
  if (!node) return;
  const Scene& scene = session.scene();
  const int parent = scene.nodes[*node].parent;
  const glm::mat4 parent_world =
      parent >= 0 ? scene.world_transform(uint32_t(parent)) : glm::mat4(1.0f);
  const glm::vec3 right = glm::vec3(resolve_camera(scene).camera_to_world[0]);
  const glm::vec3 offset =
      glm::vec3(glm::inverse(parent_world) * glm::vec4(0.1f * session.radius() * right, 0.0f));
  const size_t first_new = scene.nodes.size();
  if (!try_edit(session, state, DuplicateEdit{node_reference(scene, *node), "", offset})) return;
  // The copy is the first node the edit appended (its subtree follows it).
  for (size_t n = first_new; n < session.scene().nodes.size(); ++n)
    if (session.scene().nodes[n].parent == parent) {
      state.selected_node = int(n);
      break;
    }
}

void delete_selection(Session& session, ViewerState& state) {
  const std::optional<uint32_t> node = selected_node(session, state);
  if (!node) return;
  if (try_edit(session, state, DeleteEdit{node_reference(session.scene(), *node)}))
    state.selected_node = -1;
}

void drop_files(Session& session, ViewerState& state, const std::vector<std::string>& paths,
                bool shift) {
  bool opened = false;
  for (const std::string& path : paths) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (ext != ".gltf" && ext != ".glb") {
      state.error("dropped " + path + ": not a glTF scene (.gltf or .glb)");
      continue;
    }
    if (shift) {
      if (try_edit(session, state, ImportEdit{path, "", glm::vec3(0.0f)}))
        state.info("imported " + path);
      continue;
    }
    if (opened) {
      state.info("dropped " + path + ": one scene opens at a time (Shift imports them all)");
      continue;
    }
    state.open_path = path;
    state.request_open = true;
    state.open_confirmed = !session.history().unsaved();
    opened = true;
  }
}

}  // namespace hipr::viewer
