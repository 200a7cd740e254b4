#include "app/viewer/viewer_state.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/log.h"
#include "render/light_tables.h"

namespace hipr::viewer {

namespace {
constexpr size_t kKeptMessages = 50;
}

Focus view_focus(const Scene& scene, const ViewerState& state, std::optional<glm::vec2> cursor) {
  Focus focus;
  if (state.focus_selection && state.selected_node >= 0 &&
      size_t(state.selected_node) < scene.nodes.size())
    focus.seeds.push_back(focus_on_node(scene, size_t(state.selected_node)));
  if (state.focus_cursor && cursor)
    focus.seeds.push_back({.pixel = *cursor, .radius = std::max(state.focus_radius, 1.0f)});
  return focus;
}

void ViewerState::info(const std::string& text) {
  messages.push_back({text, false});
  ++message_count;
  if (messages.size() > kKeptMessages) messages.erase(messages.begin());
}

void ViewerState::error(const std::string& text) {
  messages.push_back({text, true});
  ++message_count;
  if (messages.size() > kKeptMessages) messages.erase(messages.begin());
  log::warn(text);
}

void follow_environment(const Scene& scene, ViewerState& state) {
  const std::optional<Environment>& env = scene.environment;
  const std::string key = env ? env->path.string() + " " + std::to_string(env->width) : "none";
  if (key == state.environment_key) return;
  const float radiance = env ? environment_mean_luminance(*env) : 0.0f;
  const float before = state.environment_radiance;
  if (!state.auto_exposure && !state.environment_key.empty() && before > 0.0f && radiance > 0.0f &&
      std::isfinite(before) && std::isfinite(radiance)) {
    state.exposure_ev = std::clamp(state.exposure_ev - std::log2(radiance / before), -20.0f, 20.0f);
    char text[64];
    std::snprintf(text, sizeof text, "exposure %.1f EV for the new light",
                  double(state.exposure_ev));
    state.info(text);
  }
  state.environment_key = key;
  if (radiance > 0.0f) state.environment_radiance = radiance;  // "none" in between keeps the last
}

void follow_metering(ViewerState& state, float metered_ev) {
  if (!state.auto_exposure || !std::isfinite(metered_ev)) return;
  if (std::abs(metered_ev - state.exposure_ev) > kMeteringDeadbandEv)
    state.exposure_ev = metered_ev;
}

}  // namespace hipr::viewer
