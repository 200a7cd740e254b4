// Side panel sections about the scene: tree, selection + materials, lights, environment.
#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <glm/trigonometric.hpp>

#include "app/viewer/panels.h"
#include "hipr/scene_loader.h"
#include "image/builtin_environments.h"
#include "scene/material_parameters.h"

namespace hipr::viewer {
namespace {

// Drag speed for an unbounded value: about 1% of its size, so small and large values both move.
float drag_speed(float value, float floor) { return std::max(std::abs(value) * 0.01f, floor); }

void tree_node(Session& session, ViewerState& state, uint32_t node) {
  const Scene& scene = session.scene();
  const Node& n = scene.nodes[node];
  const bool leaf = scene.children[node].empty();
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (leaf) flags |= ImGuiTreeNodeFlags_Leaf | ImGuiTreeNodeFlags_NoTreePushOnOpen;
  if (state.selected_node == int(node)) flags |= ImGuiTreeNodeFlags_Selected;
  std::string label = node_label(scene, node);
  if (n.light >= 0) label += "  (light)";
  if (n.camera >= 0) label += "  (camera)";
  ImGui::PushID(int(node));
  const bool open = ImGui::TreeNodeEx("node", flags, "%s", label.c_str());
  if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) state.selected_node = int(node);
  if (n.mesh >= 0 || !leaf) {
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - ImGui::GetFrameHeight());
    bool visible = n.visible;
    if (ImGui::Checkbox("##visible", &visible))
      ui_edit(session, state, VisibilityEdit{node_reference(scene, node), visible});
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("visible");
  }
  if (open && !leaf) {
    for (uint32_t child : scene.children[node]) tree_node(session, state, child);
    ImGui::TreePop();
  }
  ImGui::PopID();
}

void material_editor(Session& session, ViewerState& state, uint32_t material) {
  const Scene& scene = session.scene();
  const MaterialParameters& block = scene.materials[material].params;
  const std::string name = material_reference(scene, material);
  for (const MaterialParameter& p : material_parameters()) {
    float values[3] = {0.0f, 0.0f, 0.0f};
    std::memcpy(values, reinterpret_cast<const char*>(&block) + p.offset,
                size_t(p.components) * sizeof(float));
    bool changed = false;
    if (p.components == 3) {
      ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float;
      if (!(p.max <= 1.0f)) flags |= ImGuiColorEditFlags_HDR;
      changed = ImGui::ColorEdit3(p.name, values, flags);
    } else if (std::isfinite(p.min) && std::isfinite(p.max)) {
      changed = ImGui::SliderFloat(p.name, values, p.min, p.max);
    } else {
      const float lo = std::isfinite(p.min) ? p.min : -FLT_MAX,
                  hi = std::isfinite(p.max) ? p.max : FLT_MAX;
      changed = ImGui::DragFloat(p.name, values, drag_speed(values[0], 0.01f), lo, hi, "%.3f",
                                 ImGuiSliderFlags_AlwaysClamp);
    }
    if (!changed) continue;
    std::vector<float> set(values, values + p.components);
    for (float& v : set) v = std::clamp(std::isfinite(v) ? v : 0.0f, p.min, p.max);
    ui_edit(session, state, MaterialEdit{name, {{p.name, set}}});
  }
}

// KHR_materials_variants: the file's material sets, one shown (a variant edit, undoable).
void variant_list(Session& session, ViewerState& state) {
  const Scene& scene = session.scene();
  if (scene.material_variants.empty()) return;
  const int active = scene.active_variant;
  const std::string preview =
      active < 0 ? "(default materials)" : scene.material_variants[size_t(active)];
  if (ImGui::BeginCombo("material variant", preview.c_str())) {
    if (ImGui::Selectable("(default materials)", active < 0) && active >= 0)
      ui_edit(session, state, VariantEdit{""});
    for (size_t v = 0; v < scene.material_variants.size(); ++v) {
      const std::string label = std::to_string(v) + " " + scene.material_variants[v];
      if (ImGui::Selectable(label.c_str(), int(v) == active) && int(v) != active)
        ui_edit(session, state, VariantEdit{scene.material_variants[v]});
    }
    ImGui::EndCombo();
  }
  tooltip(
      "The file's material variants (KHR_materials_variants): each gives some objects other "
      "materials. An edit script's {\"op\": \"variant\", \"name\": ...}; --variant on the "
      "command line.");
}

}  // namespace

void scene_tree_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("Scene", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::BeginChild("tree", ImVec2(0.0f, 160.0f), true);
  for (uint32_t root : session.scene().root_nodes) tree_node(session, state, root);
  ImGui::EndChild();
  variant_list(session, state);
}

void selection_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("Selection", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::optional<uint32_t> selected = selected_node(session, state);
  if (!selected) {
    ImGui::TextDisabled("Click an object in the view (or a node above).");
    return;
  }
  const uint32_t node = *selected;
  ImGui::Text("%s", node_label(session.scene(), node).c_str());
  ImGui::SameLine();
  if (ImGui::SmallButton("Duplicate")) {  // Ctrl+D
    duplicate_selection(session, state);
    return;  // the selection is the copy now: drawn next frame
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("Delete")) {  // Delete
    delete_selection(session, state);
    return;
  }
  const Scene& scene = session.scene();
  const Node& n = scene.nodes[node];
  const std::string reference = node_reference(scene, node);
  float translation[3] = {n.local[3].x, n.local[3].y, n.local[3].z};
  const auto [lo, hi] = session.bounds();
  if (ImGui::DragFloat3("translation", translation,
                        std::max(glm::length(hi - lo) * 0.002f, 1e-4f))) {
    glm::mat4 local = n.local;
    local[3] = glm::vec4(translation[0], translation[1], translation[2], 1.0f);
    ui_edit(session, state, TransformEdit{reference, std::nullopt, local});
  }
  // Rotation and scale as the pose's parts; a changed field rebuilds the matrix from them (the
  // node's shear, if it had one, goes: glTF's TRS cannot hold it either).
  LocalPose pose = local_pose(n.local);
  if (ImGui::DragFloat3("rotation (deg)", &pose.rotation_degrees.x, 0.5f, -360.0f, 360.0f, "%.1f"))
    ui_edit(session, state, TransformEdit{reference, std::nullopt, compose_pose(pose)});
  tooltip(
      "Euler degrees about the parent's x, then y, then z axes (as an edit script's "
      "\"rotate\"); drag, or Ctrl+click to type");
  if (ImGui::DragFloat3("scale", &pose.scale.x, 0.005f, 0.001f, 1000.0f, "%.3f",
                        ImGuiSliderFlags_AlwaysClamp))
    ui_edit(session, state, TransformEdit{reference, std::nullopt, compose_pose(pose)});
  int mode = int(state.gizmo_mode);
  ImGui::RadioButton("move (W)", &mode, int(GizmoMode::Translate));
  ImGui::SameLine();
  ImGui::RadioButton("rotate (E)", &mode, int(GizmoMode::Rotate));
  ImGui::SameLine();
  ImGui::RadioButton("scale (R)", &mode, int(GizmoMode::Scale));
  state.gizmo_mode = GizmoMode(mode);
  bool local = state.gizmo_space == GizmoSpace::Local;
  if (ImGui::Checkbox("local axes (Q)", &local))
    state.gizmo_space = local ? GizmoSpace::Local : GizmoSpace::World;
  tooltip(
      "The gizmo over the selection: drag a handle to move, turn or scale along its axis "
      "(the centre box scales evenly: drag right or up to grow); hold Ctrl to snap (15 degrees, "
      "tenths of the scale, "
      "round steps of a move). Scale handles always follow the object's own axes.");
  bool visible = n.visible;
  if (ImGui::Checkbox("visible", &visible))
    ui_edit(session, state, VisibilityEdit{reference, visible});
  if (n.mesh < 0) return;
  // Each material of the mesh once, in primitive order.
  std::vector<uint32_t> materials;
  for (const MeshPrimitive& p : scene.meshes[size_t(n.mesh)].primitives)
    if (std::find(materials.begin(), materials.end(), p.material) == materials.end())
      materials.push_back(p.material);
  for (uint32_t m : materials) {
    ImGui::PushID(int(m));
    const std::string title =
        "material " +
        (scene.materials[m].name.empty() ? "#" + std::to_string(m) : scene.materials[m].name);
    if (ImGui::TreeNodeEx("material", materials.size() == 1 ? ImGuiTreeNodeFlags_DefaultOpen : 0,
                          "%s", title.c_str())) {
      material_editor(session, state, m);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

void lights_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("Lights")) return;
  const Scene& scene = session.scene();
  bool any = false;
  for (uint32_t node : scene.light_nodes()) {
    any = true;
    const PunctualLight& light = scene.lights[size_t(scene.nodes[node].light)];
    const std::string reference = node_reference(scene, node);
    ImGui::PushID(int(node));
    ImGui::Text("%s", node_label(scene, node).c_str());
    float intensity = light.intensity;
    if (ImGui::DragFloat("intensity", &intensity, drag_speed(intensity, 0.01f), 0.0f, FLT_MAX,
                         "%.3f", ImGuiSliderFlags_AlwaysClamp))
      ui_edit(session, state,
              LightEdit{reference, std::max(intensity, 0.0f), std::nullopt, std::nullopt});
    float colour[3] = {light.color.r, light.color.g, light.color.b};
    if (ImGui::ColorEdit3("colour", colour, ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR))
      ui_edit(session, state,
              LightEdit{reference, std::nullopt,
                        glm::max(glm::vec3(colour[0], colour[1], colour[2]), glm::vec3(0.0f)),
                        std::nullopt});
    float range = light.range;
    if (ImGui::DragFloat("range (0: infinite)", &range, drag_speed(range, 0.01f), 0.0f, FLT_MAX,
                         "%.3f", ImGuiSliderFlags_AlwaysClamp))
      ui_edit(session, state,
              LightEdit{reference, std::nullopt, std::nullopt, std::max(range, 0.0f)});
    ImGui::Separator();
    ImGui::PopID();
  }
  // Emissive as the light tables see it: luminance and colour both non-zero (glTF gives every
  // material luminance 1 and a black colour, which an emission texture only multiplies).
  for (uint32_t m = 0; m < scene.materials.size(); ++m) {
    const MaterialParameters& p = scene.materials[m].params;
    if (material_emits(p)) state.emitters.insert(m);
  }
  for (uint32_t m : state.emitters) {
    any = true;
    const MaterialParameters& block = scene.materials[m].params;
    const std::string reference = material_reference(scene, m);
    ImGui::PushID(int(1000000 + m));
    ImGui::Text("emitter: material %s", scene.materials[m].name.empty()
                                            ? reference.c_str()
                                            : scene.materials[m].name.c_str());
    float luminance = block.emission_luminance;
    if (ImGui::DragFloat("emission (nits)", &luminance, drag_speed(luminance, 0.01f), 0.0f, FLT_MAX,
                         "%.3f", ImGuiSliderFlags_AlwaysClamp))
      ui_edit(session, state,
              MaterialEdit{reference, {{"emission_luminance", {std::max(luminance, 0.0f)}}}});
    float colour[3] = {block.emission_color.r, block.emission_color.g, block.emission_color.b};
    if (ImGui::ColorEdit3("emission colour", colour,
                          ImGuiColorEditFlags_Float | ImGuiColorEditFlags_HDR))
      ui_edit(session, state,
              MaterialEdit{reference,
                           {{"emission_color",
                             {std::max(colour[0], 0.0f), std::max(colour[1], 0.0f),
                              std::max(colour[2], 0.0f)}}}});
    ImGui::Separator();
    ImGui::PopID();
  }
  if (!any) ImGui::TextDisabled("No lights or emissive materials.");
}

namespace {

// The sky's sun and haze; each slider re-makes the sky (a drag is one undo step).
void sun_controls(Session& session, ViewerState& state, const SkyParameters& sky) {
  float elevation = sky.sun_elevation_degrees, azimuth = sky.sun_azimuth_degrees,
        turbidity = sky.turbidity;
  if (ImGui::SliderFloat("sun elevation", &elevation, 0.0f, 90.0f, "%.1f deg",
                         ImGuiSliderFlags_AlwaysClamp))
    ui_edit(session, state, EnvironmentEdit{.sun_elevation_degrees = elevation});
  if (ImGui::SliderFloat("sun azimuth", &azimuth, -180.0f, 180.0f, "%.1f deg",
                         ImGuiSliderFlags_AlwaysClamp))
    ui_edit(session, state, EnvironmentEdit{.sun_azimuth_degrees = azimuth});
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("0: behind the default camera, 90: toward +X");
  if (ImGui::SliderFloat("turbidity", &turbidity, kMinTurbidity, kMaxTurbidity, "%.2f",
                         ImGuiSliderFlags_AlwaysClamp))
    ui_edit(session, state, EnvironmentEdit{.turbidity = turbidity});
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("haze: 2 clear, 6 hazy, 10 murky");
}

}  // namespace

void environment_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("Environment")) return;
  const Scene& scene = session.scene();
  const std::optional<Environment>& env = scene.environment;
  const std::string current = env ? env->path.string() : std::string(kNoEnvironment);
  if (!is_environment_name(current))
    state.environment_file = current;  // offered again after switching away
  ImGui::TextWrapped("%s", environment_description(scene).c_str());

  // What lights the scene from afar: an undoable edit, HiPR re-renders.
  std::vector<std::string> choices = {kNoEnvironment, kStudioEnvironmentName, kSkyEnvironmentName};
  if (!state.environment_file.empty()) choices.push_back(state.environment_file);
  const auto label = [](const std::string& choice) {
    return is_environment_name(choice) ? choice : std::filesystem::path(choice).filename().string();
  };
  if (ImGui::BeginCombo("source##env", label(current).c_str())) {
    for (const std::string& choice : choices)
      if (ImGui::Selectable(label(choice).c_str(), choice == current) && choice != current)
        ui_edit(session, state, EnvironmentEdit{.source = std::filesystem::path(choice)});
    ImGui::EndCombo();
  }
  char path[512] = {};
  std::snprintf(path, sizeof path, "%s", state.environment_input.c_str());
  if (ImGui::InputText("file##env", path, sizeof path)) state.environment_input = path;
  ImGui::SameLine();
  if (ImGui::Button("use") && !state.environment_input.empty())
    ui_edit(session, state,
            EnvironmentEdit{.source = std::filesystem::path(state.environment_input)});
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("an equirectangular .hdr or .exr");

  if (!env) {
    ImGui::TextDisabled("Nothing lights the scene from afar.");
    return;
  }
  if (env->path == kSkyEnvironmentName) sun_controls(session, state, env->sky);
  float intensity = env->intensity;
  if (ImGui::DragFloat("intensity##env", &intensity, drag_speed(intensity, 0.01f), 0.0f, FLT_MAX,
                       "%.3f", ImGuiSliderFlags_AlwaysClamp))
    ui_edit(session, state, EnvironmentEdit{.intensity = std::max(intensity, 0.0f)});
  float degrees = glm::degrees(env->rotation);
  if (ImGui::SliderFloat("rotation (deg)", &degrees, -180.0f, 180.0f))
    ui_edit(session, state, EnvironmentEdit{.rotation = glm::radians(degrees)});
}

}  // namespace hipr::viewer
