#include "scene/gltf_light_writer.h"

#include <algorithm>

#include "core/error.h"
#include "scene/gltf_hipr_extras.h"

namespace hipr::gltf {
namespace {

// Whether the light's colour loads as `color`: the loader keeps max(colour, 0), white when absent.
bool color_loads_as(const Json& light, const glm::vec3& color) {
  const std::vector<double> c = json_numbers(light, "color");
  if (c.size() < 3) return light.contains("color") ? false : color == glm::vec3(1.0f);
  return glm::max(glm::vec3(float(c[0]), float(c[1]), float(c[2])), glm::vec3(0.0f)) == color;
}

void write_light(Json& json, const PunctualLight& light, const std::string& what) {
  erase_extra(json, kLightExtras);  // recomputed from the light
  const bool same =
      color_loads_as(json, light.color) && loads_as(json, "intensity", {light.intensity}, {1.0f});
  const float peak = std::max({light.color.r, light.color.g, light.color.b});
  if (!same) {
    // KHR_lights_punctual caps colour components at 1: keep the product, the light itself.
    const float scale = std::max(peak, 1.0f);
    const glm::vec3 color = light.color / scale;
    put_numbers(json, "color", {color.r, color.g, color.b}, {color.r, color.g, color.b},
                {1.0f, 1.0f, 1.0f});
    put_number(json, "intensity", light.intensity * scale, light.intensity * scale, 1.0f);
  }
  if (peak > 1.0f && !same) {
    Json exact = {
        {"color",
         {json_number(light.color.r), json_number(light.color.g), json_number(light.color.b)}},
        {"intensity", json_number(light.intensity)}};
    set_extra(json, kLightExtras, std::move(exact), what);
  }
  // range: 0 is infinite, which glTF says by leaving it out.
  if (!loads_as(json, "range", {light.range}, {0.0f})) {
    if (light.range > 0.0f)
      json["range"] = json_number(light.range);
    else
      json.erase("range");
  }
}

Json new_light(const PunctualLight& light, const std::string& what) {
  Json json = Json::object();
  if (!light.name.empty()) json["name"] = light.name;
  json["type"] = light.type == LightType::Point  ? "point"
                 : light.type == LightType::Spot ? "spot"
                                                 : "directional";
  if (light.type == LightType::Spot)
    json["spot"] = {{"innerConeAngle", json_number(light.inner_cone)},
                    {"outerConeAngle", json_number(light.outer_cone)}};
  write_light(json, light, what);
  return json;
}

}  // namespace

void write_lights(Json& doc, const std::vector<PunctualLight>& lights, const std::string& name) {
  Json* list = nullptr;
  if (doc.contains("extensions") && doc["extensions"].is_object() &&
      doc["extensions"].contains("KHR_lights_punctual") &&
      doc["extensions"]["KHR_lights_punctual"].is_object() &&
      doc["extensions"]["KHR_lights_punctual"].contains("lights"))
    list = &doc["extensions"]["KHR_lights_punctual"]["lights"];
  const size_t count = list && list->is_array() ? list->size() : 0;
  if (count > lights.size())
    throw InputError(name + ": the scene has " + std::to_string(lights.size()) +
                     " punctual lights but its file " + std::to_string(count) +
                     ": the file changed since it was loaded");
  for (size_t i = 0; i < count; ++i)
    write_light((*list)[i], lights[i], name + ": light " + std::to_string(i));
  if (count == lights.size()) return;
  // Lights edits added (a duplicated lamp): appended, written whole.
  if (!list) {
    doc["extensions"]["KHR_lights_punctual"]["lights"] = Json::array();
    list = &doc["extensions"]["KHR_lights_punctual"]["lights"];
  }
  for (size_t i = count; i < lights.size(); ++i)
    list->push_back(new_light(lights[i], name + ": light " + std::to_string(i)));
}

}  // namespace hipr::gltf
