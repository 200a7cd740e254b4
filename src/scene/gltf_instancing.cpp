#include "scene/gltf_instancing.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include "core/error.h"
#include "scene/gltf_accessors.h"

namespace hipr::gltf {

std::vector<glm::mat4> gpu_instance_transforms(const tinygltf::Model& model,
                                               const tinygltf::Value& ext,
                                               const std::string& what) {
  if (!ext.IsObject() || !ext.Has("attributes") || !ext.Get("attributes").IsObject())
    throw InputError(what + " has no attributes object");
  const tinygltf::Value& attributes = ext.Get("attributes");
  size_t count = 0;
  bool any = false;
  const auto read = [&](const char* name, int components) {
    std::vector<float> values;
    if (!attributes.Has(name)) return values;
    const tinygltf::Value& index = attributes.Get(name);
    if (!index.IsInt()) throw InputError(what + ": " + name + " is not an accessor index");
    values = read_floats(model, index.Get<int>(), components, what + " " + name);
    const size_t n = values.size() / size_t(components);
    if (any && n != count) throw InputError(what + ": its attributes have different counts");
    count = n;
    any = true;
    return values;
  };
  const std::vector<float> t = read("TRANSLATION", 3), r = read("ROTATION", 4),
                           s = read("SCALE", 3);
  if (!any) throw InputError(what + " has none of TRANSLATION, ROTATION and SCALE");
  std::vector<glm::mat4> out(count);
  for (size_t k = 0; k < count; ++k) {
    glm::mat4 m(1.0f);
    if (!t.empty()) m = glm::translate(m, glm::vec3(t[3 * k], t[3 * k + 1], t[3 * k + 2]));
    if (!r.empty()) {
      const glm::quat q(r[4 * k + 3], r[4 * k], r[4 * k + 1], r[4 * k + 2]);  // glTF: x y z w
      const float length = glm::length(q);
      if (!(length > 0.0f))
        throw InputError(what + ": instance " + std::to_string(k) +
                         " has a zero rotation quaternion");
      m = m * glm::mat4_cast(q / length);
    }
    if (!s.empty()) m = glm::scale(m, glm::vec3(s[3 * k], s[3 * k + 1], s[3 * k + 2]));
    out[k] = m;
  }
  return out;
}

}  // namespace hipr::gltf
