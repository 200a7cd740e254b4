// KHR_materials_variants: which material each primitive shows (hipr/edits.h).
#include <string>

#include "core/error.h"
#include "hipr/edits.h"

namespace hipr {

int find_material_variant(const Scene& scene, const std::string& name) {
  if (name.empty()) return -1;
  const std::vector<std::string>& variants = scene.material_variants;
  for (size_t v = 0; v < variants.size(); ++v)
    if (variants[v] == name) return int(v);
  if (name.find_first_not_of("0123456789") == std::string::npos && name.size() < 6 &&
      std::stoul(name) < variants.size())
    return int(std::stoul(name));
  if (variants.empty())
    throw InputError("the scene has no material variants (asked for '" + name + "')");
  std::string list;
  for (size_t v = 0; v < variants.size(); ++v)
    list += (v ? ", " : "") + std::to_string(v) + " '" + variants[v] + "'";
  throw InputError("no material variant '" + name + "' (the scene has " + list + ")");
}

void select_material_variant(Scene& scene, int variant) {
  if (variant >= int(scene.material_variants.size()))
    throw InternalError("material variant " + std::to_string(variant) + " out of range");
  scene.active_variant = variant < 0 ? -1 : variant;
  for (Mesh& mesh : scene.meshes)
    for (MeshPrimitive& p : mesh.primitives) {
      p.material = p.default_material;
      for (const MeshPrimitive::VariantMaterial& m : p.variant_materials)
        if (int(m.variant) == scene.active_variant) p.material = m.material;
    }
}

}  // namespace hipr
