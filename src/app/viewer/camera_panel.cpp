// The Camera section of the side panel: the cameras the scene defines (look through one: a
// camera edit, which HiPR reprojects), and the thin lens (aperture radius, focus distance,
// click to focus: each a camera edit, undoable, converging to the lens render).
#include <imgui.h>

#include <algorithm>

#include "app/viewer/panels.h"
#include "scene/default_camera.h"

namespace hipr::viewer {

void camera_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("Camera")) return;
  const Scene& scene = session.scene();
  const std::vector<uint32_t> cameras = scene.camera_nodes();
  const int active = scene.camera_node();
  if (cameras.empty()) ImGui::TextDisabled("the default view (the file has no camera)");
  for (size_t i = 0; i < cameras.size(); ++i) {
    const std::string label = std::to_string(i) + " " + camera_label(scene, cameras[i]);
    if (ImGui::RadioButton(label.c_str(), int(cameras[i]) == active) && int(cameras[i]) != active) {
      CameraEdit edit;
      edit.use = "#" + std::to_string(cameras[i]);
      ui_edit(session, state, edit);
    }
  }
  const Camera camera = resolve_camera(scene);
  const float radius = std::max(session.radius(), 1e-4f);
  float aperture = camera.aperture_radius;
  if (ImGui::SliderFloat("lens radius", &aperture, 0.0f, 0.1f * radius, "%.4f",
                         ImGuiSliderFlags_AlwaysClamp)) {
    CameraEdit edit;
    edit.aperture_radius = aperture;
    ui_edit(session, state, edit);
  }
  tooltip(
      "Depth of field: 0 is a pinhole (everything sharp); larger blurs what is off the "
      "focus distance more. An edit script's camera \"aperture\".");
  float focus = camera.focus_distance;
  if (ImGui::DragFloat("focus distance", &focus, 0.002f * radius, 1e-4f * radius, 1e6f, "%.3f",
                       ImGuiSliderFlags_AlwaysClamp)) {
    CameraEdit edit;
    edit.focus_distance = focus;
    ui_edit(session, state, edit);
  }
  if (ImGui::Button(state.pick_focus ? "click the image..." : "click to focus"))
    state.pick_focus = !state.pick_focus;
  tooltip(
      "The next click on the image sets the focus distance to the surface there (its depth "
      "along the view axis), instead of selecting.");
}

}  // namespace hipr::viewer
