// The side panel's frame and its viewer sections (file, history, HiPR, display), the status
// line, and how widget edits reach the session.
#include "app/viewer/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>

#include "app/cli_common.h"
#include "core/error.h"
#include "image/builtin_environments.h"
#include "vk/buffer.h"

namespace hipr::viewer {
namespace {

// The oracle needs a reference render of every edit: a benchmark's policy, not a viewer's.
const Policy kPolicies[] = {Policy::Hipr, Policy::Full, Policy::Scanline, Policy::Spiral,
                            Policy::Random};

// The HiPR panel's widgets for the scheduling settings, drawn from their declaration
// (for_each_schedule_setting); start-up-only settings are left to the flags.
struct ScheduleWidgets {
  Policy policy;  // the one in use (the display rule's default is its own)
  static void tooltip(const ScheduleSettingInfo& info) { viewer::tooltip(info.help); }
  void operator()(const ScheduleSettingInfo& info, Policy& chosen) const {
    if (ImGui::BeginCombo(info.name, policy_name(chosen).c_str())) {
      for (Policy p : kPolicies)
        if (ImGui::Selectable(policy_name(p).c_str(), p == chosen)) chosen = p;
      ImGui::EndCombo();
    }
    tooltip(info);
  }
  void operator()(const ScheduleSettingInfo& info, std::optional<DisplayRule>& rule) const {
    const std::string label =
        rule ? display_rule_name(*rule)
             : "default (" + display_rule_name(default_display_rule(policy)) + ")";
    if (ImGui::BeginCombo(info.name, label.c_str())) {
      if (ImGui::Selectable("default", !rule)) rule.reset();
      for (DisplayRule r : {DisplayRule::Immediate, DisplayRule::Switch, DisplayRule::Blend,
                            DisplayRule::Difference})
        if (ImGui::Selectable(display_rule_name(r).c_str(), rule == r)) rule = r;
      ImGui::EndCombo();
    }
    tooltip(info);
  }
  void operator()(const ScheduleSettingInfo& info, bool& on) const {
    ImGui::Checkbox(info.name, &on);
    tooltip(info);
  }
  void operator()(const ScheduleSettingInfo& info, uint32_t& value) const {
    if (!info.live) return;
    int v = int(value);
    if (ImGui::SliderInt(info.name, &v, int(info.min), int(info.max)))
      value = uint32_t(std::max(v, int(info.min)));
    tooltip(info);
  }
};

// Weights as the renderer takes them: each group scaled to sum 1 (left alone when all zero).
HiprParameters normalised(HiprParameters h) {
  const auto normalise = [](float* w, int n) {
    float sum = 0.0f;
    for (int i = 0; i < n; ++i) sum += w[i];
    if (sum > 0.0f)
      for (int i = 0; i < n; ++i) w[i] /= sum;
  };
  normalise(h.w_lobe, 4);
  normalise(h.w_path, 3);
  return h;
}

void file_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const EditHistory& history = session.history();
  ImGui::InputText("##open", &state.open_path);
  ImGui::SameLine();
  if (ImGui::Button("Open")) {
    state.request_open = true;
    state.open_confirmed = !history.unsaved();
  }
  if (state.request_open && !state.open_confirmed) {
    ImGui::TextColored(ImVec4(1.0f, 0.7f, 0.3f, 1.0f), "Unsaved edits will be lost.");
    if (ImGui::Button("Open anyway")) state.open_confirmed = true;
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) state.request_open = false;
  }
  ImGui::InputText("##save", &state.save_path);
  ImGui::SameLine();
  if (ImGui::Button("Save")) state.request_save = true;
  // A glTF file's scene, added as one new object (at its own origin).
  ImGui::InputText("##import", &state.import_path);
  ImGui::SameLine();
  if (ImGui::Button("Import") && !state.import_path.empty())
    try_edit(session, state, ImportEdit{state.import_path, "", glm::vec3(0.0f)});
  ImGui::InputText("##shot", &state.screenshot_path);
  ImGui::SameLine();
  if (ImGui::Button("Screenshot")) state.request_screenshot = true;
  // Messages, newest last (errors in red), in a box of fixed height: a new message must not
  // move the widgets below it under the user's mouse.
  ImGui::BeginChild("messages", ImVec2(0.0f, 3.0f * ImGui::GetTextLineHeightWithSpacing() + 6.0f),
                    true);
  for (const Message& m : state.messages) {
    if (m.error) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.4f, 0.35f, 1.0f));
    ImGui::TextWrapped("%s", m.text.c_str());
    if (m.error) ImGui::PopStyleColor();
  }
  if (state.message_count != state.messages_shown)
    ImGui::SetScrollHereY(1.0f);  // follow the newest
  state.messages_shown = state.message_count;
  ImGui::EndChild();
}

void history_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("History", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const EditHistory& history = session.history();
  ImGui::BeginDisabled(!history.can_undo());
  if (ImGui::Button("Undo")) session.undo();
  ImGui::EndDisabled();
  if (history.can_undo()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", history.undo_label().c_str());
  }
  ImGui::BeginDisabled(!history.can_redo());
  if (ImGui::Button("Redo")) session.redo();
  ImGui::EndDisabled();
  if (history.can_redo()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", history.redo_label().c_str());
  }
  ImGui::Text("%zu step(s)%s", history.undo_count(), history.unsaved() ? ", unsaved" : "");
  (void)state;
}

void hipr_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("HiPR")) return;
  const SessionSettings& settings = session.settings();
  ScheduleSettings edited = settings.schedule;
  for_each_schedule_setting(edited, ScheduleWidgets{settings.schedule.policy});
  if (edited != settings.schedule) state.request_schedule = edited;
  ImGui::Checkbox("focus: selection", &state.focus_selection);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "hipr renders where the selected object is seen first, then where its light goes");
  ImGui::SameLine();
  ImGui::Checkbox("cursor", &state.focus_cursor);
  if (state.focus_cursor)
    ImGui::SliderFloat("focus radius (px)", &state.focus_radius, 4.0f, 256.0f, "%.0f");
  ImGui::InputInt("n (tile px)", &state.tile_size_input);
  state.tile_size_input = std::clamp(state.tile_size_input, 1, 256);
  ImGui::SameLine();
  if (ImGui::Button("Apply")) state.request_tile_size = uint32_t(state.tile_size_input);
  if (ImGui::BeginCombo("sampler", sampler_name(settings.render.sampler))) {
    for (Sampler s : {Sampler::Sobol, Sampler::Random})
      if (ImGui::Selectable(sampler_name(s), s == settings.render.sampler))
        state.request_sampler = s;
    ImGui::EndCombo();
  }
  if (ImGui::BeginCombo("light selection", light_selection_name(settings.render.light_selection))) {
    for (LightSelection s : {LightSelection::Tree, LightSelection::Power})
      if (ImGui::Selectable(light_selection_name(s), s == settings.render.light_selection))
        state.request_light_selection = s;
    ImGui::EndCombo();
  }
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "tree: each point samples the lights that can reach it; power: by power alone");
  bool guiding = settings.render.guiding;
  if (ImGui::Checkbox("path guiding", &guiding)) state.request_guiding = guiding;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "learn where light comes from at each edit (a short training pass) and "
        "aim paths there too");
  ImGui::TextDisabled("n, the sampler, lights and guiding restart the image;");
  ImGui::TextDisabled("weights apply from the next edit");

  bool changed = false;
  if (ImGui::BeginCombo("preset", state.preset.c_str())) {
    for (const std::string& name : hipr_preset_names())
      if (ImGui::Selectable(name.c_str(), name == state.preset)) {
        state.preset = name;
        apply_hipr_preset(name, state.hipr_sliders);
        changed = true;
      }
    ImGui::EndCombo();
  }
  HiprParameters& h = state.hipr_sliders;
  changed |= ImGui::SliderFloat("eps", &h.depth_epsilon, 0.0005f, 0.2f, "%.4f",
                                ImGuiSliderFlags_Logarithmic);
  const char* lobes[] = {"w_lobe diffuse", "w_lobe glossy", "w_lobe specular",
                         "w_lobe transmission"};
  for (int i = 0; i < 4; ++i) changed |= ImGui::SliderFloat(lobes[i], &h.w_lobe[i], 0.0f, 1.0f);
  const char* paths[] = {"w_path direct", "w_path indirect", "w_path caustic"};
  for (int i = 0; i < 3; ++i) changed |= ImGui::SliderFloat(paths[i], &h.w_path[i], 0.0f, 1.0f);
  changed |= ImGui::SliderFloat("w_occlusion", &h.w_occlusion, 0.0f, 2.0f);
  if (changed) session.set_hipr_parameters(normalised(h));
  ImGui::TextWrapped(
      "%u tiles of %u px, %u per step; %u spp per visit (first visit %u), target %u spp",
      session.renderer().tile_count(), settings.render.tile_size,
      settings.schedule.tiles_per_step ? settings.schedule.tiles_per_step
                                       : viewer_tiles_per_step(session.renderer().tile_count()),
      settings.schedule.visit_spp,
      settings.schedule.first_visit_spp ? settings.schedule.first_visit_spp
                                        : default_first_visit_spp(settings),
      settings.spp);
}

// The denoiser's widgets, one per setting of its declaration (hipr/denoise.h).
struct DenoiseWidgets {
  bool enabled;  // the settings past the toggle show only while it is on
  void operator()(const DenoiseSettingInfo& info, bool& value) const {
    if (std::string(info.flag) != "--denoise" && !enabled) return;
    ImGui::Checkbox(
        std::string(info.name).append(std::string(info.flag) == "--denoise" ? " (N)" : "").c_str(),
        &value);
    tooltip(info.help);
  }
  void operator()(const DenoiseSettingInfo& info, float& value) const {
    if (!enabled) return;
    ImGui::SliderFloat(info.name, &value, info.min, info.max, "%.2f");
    tooltip(info.help);
  }
  void operator()(const DenoiseSettingInfo& info, uint32_t& value) const {
    if (!enabled) return;
    int n = int(value);
    if (ImGui::SliderInt(info.name, &n, int(info.min), int(info.max))) value = uint32_t(n);
    tooltip(info.help);
  }
};

// The convergence targets' widgets, one per setting of their declaration (hipr/convergence.h).
struct ConvergenceWidgets {
  bool& changed;
  void operator()(const ConvergenceSettingInfo& info, double& value) const {
    // Logarithmic sliders reach the small values that matter (a relMSE of 1e-4, a second);
    // 0, the slider's far left, turns the target off.
    float v = float(value);
    if (ImGui::SliderFloat(info.name, &v, float(info.min), float(std::min(info.max, 600.0)),
                           v == 0.0f ? "off" : "%.3g", ImGuiSliderFlags_Logarithmic)) {
      value = v;
      changed = true;
    }
    tooltip(info.help);
  }
  void operator()(const ConvergenceSettingInfo& info, bool& value) const {
    changed |= ImGui::Checkbox(info.name, &value);
    tooltip(info.help);
  }
};

void convergence_section(Session& session, ViewerState& state) {
  if (!ImGui::CollapsingHeader("Convergence")) return;
  uint32_t spp = session.settings().spp;
  ConvergenceTarget target = session.settings().converge;
  bool changed = false;
  int n = int(std::min(spp, 1u << 20));
  if (ImGui::SliderInt("spp (at most)", &n, 1, 1 << 16, "%d", ImGuiSliderFlags_Logarithmic)) {
    spp = uint32_t(std::max(n, 1));
    changed = true;
  }
  tooltip("Rendering pauses at this many samples per pixel since the last change (--spp)");
  for_each_convergence_setting(target, ConvergenceWidgets{changed});
  if (changed) state.request_convergence = std::pair{spp, target};
  if (const auto& noise = session.noise())
    ImGui::Text("noise: relMSE %.3g (%s)", noise->relmse,
                noise->unknown_pixels ? "some pixels unknown" : "estimated");
  ImGui::TextDisabled("the time and noise targets wait for every pixel to show the scene");
  if (state.denoise.enabled && !session.shows_denoised(state.denoise))
    ImGui::Text("clean: the window shows the raw image");
}

void display_section(ViewerState& state) {
  if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
  int overlay = int(state.overlay);
  const char* names[] = {"none", "object ids", "tile weights", "owed tiles"};
  ImGui::Combo("overlay (0-3)", &overlay, names, 4);
  state.overlay = Overlay(overlay);
  // Setting the exposure by hand locks it; "auto" meters it again.
  if (ImGui::SliderFloat("exposure (EV)", &state.exposure_ev, -20.0f, 20.0f, "%.1f"))
    state.auto_exposure = false;
  ImGui::Checkbox("auto exposure", &state.auto_exposure);
  tooltip(
      "Meter the exposure from the image: its brightest tenth of surfaces just under white "
      "(--exposure auto). Moving the slider locks it.");
  int mapper = int(state.tone_mapper);
  std::vector<std::string> names_owned;
  for (ToneMapper m : tone_mappers()) names_owned.push_back(tone_mapper_name(m));
  std::vector<const char*> mapper_names;
  for (const std::string& n : names_owned) mapper_names.push_back(n.c_str());
  if (ImGui::Combo("tone mapper", &mapper, mapper_names.data(), int(mapper_names.size())))
    state.tone_mapper = ToneMapper(mapper);
  tooltip(
      "After the exposure (--tonemap): clamp, Khronos PBR Neutral (glTF colours as "
      "authored), AgX (Blender's default) or ACES");
  for_each_denoise_setting(state.denoise, DenoiseWidgets{state.denoise.enabled});
  ImGui::Checkbox("status line", &state.show_status);
  bool adapt = state.frame_budget_ms <= 0.0;
  if (ImGui::Checkbox("adapt render time (60 fps)", &adapt))
    state.frame_budget_ms = adapt ? 0.0 : 30.0;
  if (adapt) {
    ImGui::Text("render %.1f ms/frame", state.adaptive_budget_ms);
  } else {
    float budget = float(state.frame_budget_ms);
    if (ImGui::SliderFloat("render ms/frame", &budget, 2.0f, 250.0f, "%.0f",
                           ImGuiSliderFlags_Logarithmic))
      state.frame_budget_ms = budget;
  }
}

}  // namespace

void tooltip(const char* help) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 30.0f);
  ImGui::TextUnformatted(help);
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

bool ui_edit(Session& session, ViewerState& state, const Edit& edit) {
  if (!state.ui_group_open && ImGui::IsAnyItemActive()) {
    session.begin_group();
    state.ui_group_open = true;
  }
  return try_edit(session, state, edit);
}

void end_ui_edit_group(Session& session, ViewerState& state) {
  if (state.ui_group_open && !ImGui::IsAnyItemActive()) {
    session.end_group();
    state.ui_group_open = false;
  }
}

void draw_side_panel(Session& session, ViewerState& state, float x, float height) {
  ImGui::SetNextWindowPos(ImVec2(x, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, height), ImGuiCond_Always);
  ImGui::Begin("hipr", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse);
  ImGui::PushItemWidth(-150.0f);
  file_section(session, state);
  history_section(session, state);
  display_section(state);
  scene_tree_section(session, state);
  selection_section(session, state);
  camera_section(session, state);
  lights_section(session, state);
  environment_section(session, state);
  hipr_section(session, state);
  convergence_section(session, state);
  ImGui::PopItemWidth();
  ImGui::End();
}

void draw_status_line(const Session& session, const ViewerState& state, float x, float y,
                      float width) {
  char buffer[96];
  std::vector<std::string> items;
  const auto add = [&](const char* format, auto... values) {
    std::snprintf(buffer, sizeof buffer, format, values...);
    items.emplace_back(buffer);
  };
  add("%s", policy_name(session.settings().schedule.policy).c_str());
  add("%.1f/%u spp", state.mean_spp, session.settings().spp);
  if (const auto& noise = session.noise())
    add("relMSE %.2g/%.2g", noise->relmse, session.settings().converge.relmse);
  add("work %.2f", session.work_since_edit());
  add("%.1f s since edit", session.seconds_since_edit());
  add("%.2f Msamples/s", session.samples_per_second() * 1e-6);
  add("%.1f fps", state.fps);
  // What the scene costs (BENCHMARKS.md "Big scenes"): triangles drawn, and every buffer and
  // image hipr holds on the device.
  add("%.2f M triangles", double(session.renderer().scene_stats().triangle_count) * 1e-6);
  add("%.0f MiB on the device", double(vk::device_bytes_in_use()) / double(1 << 20));
  // Which light from afar the image uses (the built-in studio lights a scene with no light).
  if (session.scene().environment) add("env %s", environment_description(session.scene()).c_str());
  const auto& records = session.edit_records();
  if (!records.empty() && records.back().latency_seconds >= 0.0)
    add("latency %.0f ms", records.back().latency_seconds * 1e3);
  if (!session.focus().empty() && session.settings().schedule.policy == Policy::Hipr)
    add("focus: %zu seed%s", session.focus().seeds.size(),
        session.focus().seeds.size() == 1 ? "" : "s");
  if (session.converged()) add("converged");
  // Items flow onto as many lines as the view's width needs (the view can be as narrow as
  // the render).
  const ImGuiStyle& style = ImGui::GetStyle();
  const float gap = ImGui::CalcTextSize("  ").x,
              usable = std::max(width - 2.0f * style.WindowPadding.x, 1.0f);
  std::vector<std::string> lines(1);
  float line_width = 0.0f;
  for (const std::string& item : items) {
    const float w = ImGui::CalcTextSize(item.c_str()).x;
    if (!lines.back().empty() && line_width + gap + w > usable) {
      lines.emplace_back();
      line_width = 0.0f;
    }
    if (!lines.back().empty()) {
      lines.back() += "  ";
      line_width += gap;
    }
    lines.back() += item;
    line_width += w;
  }
  const float height =
      float(lines.size()) * ImGui::GetTextLineHeightWithSpacing() + 2.0f * style.WindowPadding.y;
  ImGui::SetNextWindowPos(ImVec2(x, y - height), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, height), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.55f);
  ImGui::Begin("status", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoInputs |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  for (const std::string& line : lines) ImGui::TextUnformatted(line.c_str());
  ImGui::End();
}

}  // namespace hipr::viewer
