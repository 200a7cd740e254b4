#include "scene/gltf_variants.h"

#include "core/error.h"

namespace hipr::gltf {
namespace {

constexpr const char* kExtension = "KHR_materials_variants";

}  // namespace

std::vector<std::string> variant_names(const tinygltf::Model& model, const std::string& name) {
  std::vector<std::string> names;
  const auto it = model.extensions.find(kExtension);
  if (it == model.extensions.end()) return names;
  const tinygltf::Value& ext = it->second;
  if (!ext.IsObject() || !ext.Has("variants") || !ext.Get("variants").IsArray())
    throw InputError(name + ": KHR_materials_variants has no \"variants\" array");
  const tinygltf::Value& variants = ext.Get("variants");
  for (size_t v = 0; v < variants.ArrayLen(); ++v) {
    const tinygltf::Value& variant = variants.Get(int(v));
    const bool named = variant.IsObject() && variant.Has("name") && variant.Get("name").IsString();
    names.push_back(named ? variant.Get("name").Get<std::string>()
                          : "variant " + std::to_string(v));
  }
  return names;
}

std::vector<MeshPrimitive::VariantMaterial> variant_materials(const tinygltf::Model& model,
                                                              const tinygltf::Primitive& source,
                                                              size_t variant_count,
                                                              const std::string& what) {
  std::vector<MeshPrimitive::VariantMaterial> out;
  const auto it = source.extensions.find(kExtension);
  if (it == source.extensions.end()) return out;
  const tinygltf::Value& ext = it->second;
  if (!ext.IsObject() || !ext.Has("mappings") || !ext.Get("mappings").IsArray())
    throw InputError(what + ": KHR_materials_variants has no \"mappings\" array");
  const tinygltf::Value& mappings = ext.Get("mappings");
  for (size_t i = 0; i < mappings.ArrayLen(); ++i) {
    const std::string mapping_what = what + ": variant mapping " + std::to_string(i);
    const tinygltf::Value& mapping = mappings.Get(int(i));
    if (!mapping.IsObject() || !mapping.Has("material") || !mapping.Get("material").IsInt() ||
        !mapping.Has("variants") || !mapping.Get("variants").IsArray())
      throw InputError(mapping_what + " needs a material and a variants array");
    const int material = mapping.Get("material").Get<int>();
    if (material < 0 || size_t(material) >= model.materials.size())
      throw InputError(mapping_what + " references missing material " + std::to_string(material));
    const tinygltf::Value& variants = mapping.Get("variants");
    for (size_t k = 0; k < variants.ArrayLen(); ++k) {
      const tinygltf::Value& variant = variants.Get(int(k));
      const int index = variant.IsInt() ? variant.Get<int>() : -1;
      if (index < 0 || size_t(index) >= variant_count)
        throw InputError(mapping_what + " references missing variant " + std::to_string(index));
      out.push_back({uint32_t(index), uint32_t(material)});
    }
  }
  return out;
}

}  // namespace hipr::gltf
