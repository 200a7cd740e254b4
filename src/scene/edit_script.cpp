// Edit scripts (JSON) -> Edit values. Every problem names the file and the edit's position.
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include <glm/trigonometric.hpp>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/focus.h"
#include "hipr/scene_loader.h"
#include "image/builtin_environments.h"
#include "scene/material_parameters.h"

namespace hipr {
namespace {

using nlohmann::json;

class EditReader {
 public:
  EditReader(const json& edit, std::string where) : m_edit(edit), m_where(std::move(where)) {}

  [[noreturn]] void fail(const std::string& why) const { throw InputError(m_where + ": " + why); }

  std::string string(const char* key) const {
    if (!m_edit.contains(key) || !m_edit[key].is_string())
      fail(std::string("needs a string \"") + key + "\"");
    return m_edit[key];
  }

  std::vector<float> numbers(const json& value, const std::string& key) const {
    std::vector<float> out;
    if (value.is_number())
      out.push_back(value.get<float>());
    else if (value.is_array())
      for (const json& v : value) {
        if (!v.is_number()) fail("\"" + key + "\" must hold numbers");
        out.push_back(v.get<float>());
      }
    else
      fail("\"" + key + "\" must be a number or an array of numbers");
    for (float v : out)
      if (!std::isfinite(v)) fail("\"" + key + "\" holds a non-finite number");
    return out;
  }

  float number(const char* key) const {
    const auto v = numbers(m_edit[key], key);
    if (v.size() != 1) fail(std::string("\"") + key + "\" needs one number");
    return v[0];
  }

  std::optional<glm::vec3> vec3(const char* key) const {
    if (!m_edit.contains(key)) return std::nullopt;
    const auto v = numbers(m_edit[key], key);
    if (v.size() != 3) fail(std::string("\"") + key + "\" needs 3 numbers");
    return glm::vec3(v[0], v[1], v[2]);
  }

  std::optional<glm::mat4> matrix() const {
    if (!m_edit.contains("matrix")) return std::nullopt;
    const auto v = numbers(m_edit["matrix"], "matrix");
    if (v.size() != 16) fail("\"matrix\" needs 16 numbers (column-major)");
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = v[size_t(i)];
    return m;
  }

  const json& set_object() const {
    if (!m_edit.contains("set") || !m_edit["set"].is_object() || m_edit["set"].empty())
      fail("needs a non-empty object \"set\"");
    return m_edit["set"];
  }

  void only_keys(std::initializer_list<const char*> allowed) const {
    for (const auto& [key, value] : m_edit.items()) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || key == a;
      if (!ok) fail("unknown key \"" + key + "\"");
    }
  }

  const json& edit() const { return m_edit; }

 private:
  const json& m_edit;
  std::string m_where;
};

MaterialEdit read_material(const EditReader& r, bool emission_only) {
  MaterialEdit edit;
  edit.material = r.string("material");
  for (const auto& [key, value] : r.set_object().items()) {
    const MaterialParameter* parameter = find_material_parameter(key);
    if (!parameter) r.fail("unknown material parameter \"" + key + "\"");
    if (emission_only && key != "emission_luminance" && key != "emission_color")
      r.fail("an emission edit sets only emission_luminance and emission_color, not \"" + key +
             "\"");
    const auto values = r.numbers(value, key);
    if (int(values.size()) != parameter->components)
      r.fail("\"" + key + "\" needs " + std::to_string(parameter->components) + " number(s)");
    for (float v : values)
      if (v < parameter->min || v > parameter->max)
        r.fail("\"" + key + "\" = " + std::to_string(v) + " is outside [" +
               std::to_string(parameter->min) + ", " + std::to_string(parameter->max) + "]");
    edit.set.push_back({key, values});
  }
  return edit;
}

// {"op": "focus", "node": N} or {"op": "focus", "pixel": [x, y], "radius": r} (both may be
// given: one seed), with an optional "weight"; or {"op": "focus", "clear": true}.
FocusEdit read_focus(const EditReader& r) {
  r.only_keys({"op", "node", "pixel", "radius", "weight", "clear"});
  const json& e = r.edit();
  FocusEdit focus;
  if (e.contains("clear")) {
    if (!e["clear"].is_boolean() || !e["clear"].get<bool>()) r.fail("\"clear\" must be true");
    if (e.size() != 2) r.fail("a focus that clears takes nothing else");
    focus.clear = true;
    return focus;
  }
  if (e.contains("node")) focus.node = r.string("node");
  if (e.contains("pixel")) {
    const auto v = r.numbers(e["pixel"], "pixel");
    if (v.size() != 2) r.fail("\"pixel\" needs 2 numbers (x, y)");
    focus.pixel = glm::vec2(v[0], v[1]);
    if (!e.contains("radius")) r.fail("a focus pixel needs a \"radius\" in pixels");
    const auto radius = r.numbers(e["radius"], "radius");
    if (radius.size() != 1 || radius[0] <= 0.0f)
      r.fail("\"radius\" must be one positive number (pixels)");
    focus.radius = radius[0];
  } else if (e.contains("radius")) {
    r.fail("\"radius\" goes with \"pixel\"");
  }
  if (!focus.node && !focus.pixel) r.fail("a focus needs \"node\", \"pixel\" or \"clear\"");
  if (e.contains("weight")) {
    const auto weight = r.numbers(e["weight"], "weight");
    if (weight.size() != 1 || weight[0] <= 0.0f || weight[0] > kMaxFocusWeight)
      r.fail("\"weight\" must be one number in (0, " + std::to_string(int(kMaxFocusWeight)) + "]");
    focus.weight = weight[0];
  }
  return focus;
}

// A file an edit script names: relative to the script's folder, which it may not leave (neither
// by ".." nor by a link), as a scene's own files may not leave the scene's.
std::filesystem::path script_file(const EditReader& r, const std::filesystem::path& base,
                                  const std::string& name) {
  namespace fs = std::filesystem;
  const fs::path relative(name);
  if (name.empty() || relative.is_absolute() || relative.has_root_name())
    r.fail("\"" + name + "\" must be a path relative to the script's folder");
  const fs::path normal = relative.lexically_normal();
  if (!normal.empty() && *normal.begin() == "..")
    r.fail("\"" + name + "\" leaves the script's folder");
  const fs::path path = base / relative;
  std::error_code folder_error, target_error;
  const fs::path folder = fs::weakly_canonical(base.empty() ? fs::path(".") : base, folder_error);
  const fs::path target = fs::weakly_canonical(path, target_error);
  const fs::path inside = target.lexically_relative(folder);
  if (folder_error || target_error || inside.empty() || *inside.begin() == "..")
    r.fail("\"" + name + "\" leaves the script's folder");
  return path;
}

Edit read_edit(const EditReader& r, const std::filesystem::path& base) {
  if (!r.edit().is_object()) r.fail("an edit must be a JSON object");
  const std::string op = r.string("op");
  if (op == "transform") {
    r.only_keys({"op", "node", "translate", "matrix", "rotate", "scale"});
    TransformEdit e{r.string("node"), r.vec3("translate"), r.matrix(), r.vec3("rotate"),
                    r.vec3("scale")};
    const bool composed = e.translate || e.rotate || e.scale;
    if (composed == e.matrix.has_value())
      r.fail("a transform needs \"matrix\" alone, or any of \"translate\", \"rotate\", \"scale\"");
    if (e.rotate)
      for (int axis = 0; axis < 3; ++axis)
        if (!(std::abs((*e.rotate)[axis]) <= 1e6f))
          r.fail("\"rotate\" holds an angle beyond 1e6 degrees");
    if (e.scale) {  // a bad factor is refused as the script is read, with the edit's place
      try {
        transformed_local(glm::mat4(1.0f), e);
      } catch (const InputError& bad) {
        r.fail(bad.what());
      }
    }
    return e;
  }
  if (op == "material" || op == "emission") {
    r.only_keys({"op", "material", "set"});
    return read_material(r, op == "emission");
  }
  if (op == "light") {
    r.only_keys({"op", "node", "set"});
    LightEdit e;
    e.node = r.string("node");
    for (const auto& [key, value] : r.set_object().items()) {
      const auto v = r.numbers(value, key);
      if (key == "intensity" && v.size() == 1 && v[0] >= 0)
        e.intensity = v[0];
      else if (key == "color" && v.size() == 3 && v[0] >= 0 && v[1] >= 0 && v[2] >= 0)
        e.color = glm::vec3(v[0], v[1], v[2]);
      else if (key == "range" && v.size() == 1 && v[0] >= 0)
        e.range = v[0];
      else if (key != "intensity" && key != "color" && key != "range")
        r.fail("unknown light parameter \"" + key + "\"");
      else
        r.fail("invalid value for light parameter \"" + key + "\"");
    }
    return e;
  }
  if (op == "variant") {  // {"op": "variant", "name": NAME}; "" shows the default materials
    r.only_keys({"op", "name"});
    return VariantEdit{r.string("name")};
  }
  if (op == "visibility") {
    r.only_keys({"op", "node", "visible"});
    if (!r.edit().contains("visible") || !r.edit()["visible"].is_boolean())
      r.fail("needs a boolean \"visible\"");
    return VisibilityEdit{r.string("node"), r.edit()["visible"].get<bool>()};
  }
  if (op == "camera") {
    r.only_keys({"op", "translate", "matrix", "use", "aperture", "focus_distance"});
    CameraEdit e{r.vec3("translate"), r.matrix()};
    if (r.edit().contains("use")) e.use = r.string("use");
    if (r.edit().contains("aperture")) e.aperture_radius = r.number("aperture");
    if (r.edit().contains("focus_distance")) e.focus_distance = r.number("focus_distance");
    if (e.translate && e.matrix)
      r.fail("a camera edit takes \"translate\" or \"matrix\", not both");
    if (e.use && (e.translate || e.matrix || e.aperture_radius || e.focus_distance))
      r.fail("\"use\" (switching cameras) goes alone in its camera edit");
    if (!e.translate && !e.matrix && !e.use && !e.aperture_radius && !e.focus_distance)
      r.fail(
          "a camera edit needs \"translate\", \"matrix\", \"use\", \"aperture\" or "
          "\"focus_distance\"");
    if (e.aperture_radius && !(*e.aperture_radius >= 0.0f && *e.aperture_radius <= 1e6f))
      r.fail("\"aperture\" (the lens radius) must be between 0 and 1e6");
    if (e.focus_distance && !(*e.focus_distance > 0.0f && *e.focus_distance <= 1e12f))
      r.fail("\"focus_distance\" must be above 0 and at most 1e12");
    return e;
  }
  if (op == "environment") {
    r.only_keys({"op", "source", "set"});
    EnvironmentEdit e;
    if (r.edit().contains("source")) {
      const std::string source = r.string("source");
      if (source.empty()) r.fail("\"source\" is empty (studio, sky, none or a file)");
      // A file, like an import, stays inside the script's folder: a script cannot read the machine.
      e.source = is_environment_name(source) ? std::filesystem::path(source)
                                             : script_file(r, base, source);
    } else if (!r.edit().contains("set")) {
      r.fail("needs \"source\" or \"set\"");
    }
    if (r.edit().contains("set")) {
      for (const auto& [key, value] : r.set_object().items()) {
        const auto v = r.numbers(value, key);
        const bool one = v.size() == 1;
        if (key == "intensity" && one && v[0] >= 0)
          e.intensity = v[0];
        else if (key == "rotation" && one)
          e.rotation = glm::radians(v[0]);  // as --env-rotation
        else if (key == "sun_elevation" && one && v[0] >= 0 && v[0] <= 90)
          e.sun_elevation_degrees = v[0];
        else if (key == "sun_azimuth" && one)
          e.sun_azimuth_degrees = v[0];
        else if (key == "turbidity" && one && v[0] >= kMinTurbidity && v[0] <= kMaxTurbidity)
          e.turbidity = v[0];
        else if (key != "intensity" && key != "rotation" && key != "sun_elevation" &&
                 key != "sun_azimuth" && key != "turbidity")
          r.fail("unknown environment parameter \"" + key + "\"");
        else
          r.fail("invalid value for environment parameter \"" + key + "\"");
      }
    }
    if (e.sets_sun() && e.source && *e.source != kSkyEnvironmentName)
      r.fail("the sun's parameters need \"source\": \"sky\"");
    return e;
  }
  if (op == "focus") return read_focus(r);
  if (op == "duplicate") {
    r.only_keys({"op", "node", "as", "translate"});
    return DuplicateEdit{r.string("node"), r.edit().contains("as") ? r.string("as") : "",
                         r.vec3("translate").value_or(glm::vec3(0.0f))};
  }
  if (op == "delete") {
    r.only_keys({"op", "node"});
    return DeleteEdit{r.string("node")};
  }
  if (op == "import") {
    r.only_keys({"op", "file", "as", "translate"});
    return ImportEdit{script_file(r, base, r.string("file")),
                      r.edit().contains("as") ? r.string("as") : "",
                      r.vec3("translate").value_or(glm::vec3(0.0f))};
  }
  if (op == "deform") {
    r.only_keys({"op", "node", "matrix"});
    const std::optional<glm::mat4> matrix = r.matrix();
    if (!matrix) r.fail("a deform needs a \"matrix\" (16 numbers, column-major)");
    return DeformEdit{r.string("node"), *matrix, nullptr};
  }
  r.fail("unknown op \"" + op +
         "\" (transform, material, light, emission, visibility, camera, environment, focus, "
         "duplicate, delete, import, deform, variant)");
}

}  // namespace

std::vector<Edit> parse_edit_script(const std::string& text, const std::string& name,
                                    const std::filesystem::path& base) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::exception& e) {
    std::string why = e.what();
    if (const size_t at = why.find("] "); at != std::string::npos) why = why.substr(at + 2);
    throw InputError(name + ": invalid JSON: " + why);
  }
  if (!doc.is_object() || !doc.contains("edits") || !doc["edits"].is_array())
    throw InputError(name + ": an edit script is an object with an array \"edits\"");
  std::vector<Edit> edits;
  for (size_t i = 0; i < doc["edits"].size(); ++i)
    edits.push_back(
        read_edit(EditReader(doc["edits"][i], name + ": edit " + std::to_string(i)), base));
  return edits;
}

std::vector<Edit> load_edit_script(const std::filesystem::path& path) {
  std::ifstream in(path);
  if (!in) throw InputError("cannot read edit script " + path.string());
  std::stringstream text;
  text << in.rdbuf();
  return parse_edit_script(text.str(), path.filename().string(), path.parent_path());
}

}  // namespace hipr
