#include "scene/material_parameters.h"

#include <cstddef>
#include <limits>

namespace hipr {

const std::vector<MaterialParameter>& material_parameters() {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  using M = MaterialParameters;
  static const std::vector<MaterialParameter> table = {
      {"base_weight", offsetof(M, base_weight), 1, 0, 1},
      {"base_color", offsetof(M, base_color), 3, 0, 1},
      {"base_metalness", offsetof(M, base_metalness), 1, 0, 1},
      {"base_diffuse_roughness", offsetof(M, base_diffuse_roughness), 1, 0, 1},
      {"specular_weight", offsetof(M, specular_weight), 1, 0, kInf},
      {"specular_color", offsetof(M, specular_color), 3, 0, kInf},
      {"specular_roughness", offsetof(M, specular_roughness), 1, 0, 1},
      {"specular_ior", offsetof(M, specular_ior), 1, 1, kInf},
      {"specular_roughness_anisotropy", offsetof(M, specular_anisotropy), 1, 0, 1},
      {"specular_rotation", offsetof(M, specular_rotation), 1, -kInf, kInf},
      {"transmission_weight", offsetof(M, transmission_weight), 1, 0, 1},
      {"transmission_color", offsetof(M, transmission_color), 3, 0, 1},
      {"transmission_depth", offsetof(M, transmission_depth), 1, 0, kInf},
      {"transmission_dispersion_scale", offsetof(M, transmission_dispersion_scale), 1, 0, kInf},
      // Below 1 the index would swing by more than itself across the visible spectrum.
      {"transmission_dispersion_abbe_number", offsetof(M, transmission_dispersion_abbe_number), 1,
       1, kInf},
      {"subsurface_weight", offsetof(M, subsurface_weight), 1, 0, 1},
      {"subsurface_color", offsetof(M, subsurface_color), 3, 0, 1},
      {"subsurface_radius", offsetof(M, subsurface_radius), 1, 0, kInf},
      {"coat_weight", offsetof(M, coat_weight), 1, 0, 1},
      {"coat_color", offsetof(M, coat_color), 3, 0, 1},
      {"coat_roughness", offsetof(M, coat_roughness), 1, 0, 1},
      {"coat_ior", offsetof(M, coat_ior), 1, 1, kInf},
      {"coat_darkening", offsetof(M, coat_darkening), 1, 0, 1},
      {"fuzz_weight", offsetof(M, fuzz_weight), 1, 0, 1},
      {"fuzz_color", offsetof(M, fuzz_color), 3, 0, 1},
      {"fuzz_roughness", offsetof(M, fuzz_roughness), 1, 0, 1},
      {"thin_film_weight", offsetof(M, thin_film_weight), 1, 0, 1},
      {"thin_film_thickness", offsetof(M, thin_film_thickness), 1, 0, kInf},
      {"thin_film_ior", offsetof(M, thin_film_ior), 1, 1, kInf},
      {"emission_luminance", offsetof(M, emission_luminance), 1, 0, kInf},
      {"emission_color", offsetof(M, emission_color), 3, 0, kInf},
      {"geometry_opacity", offsetof(M, geometry_opacity), 1, 0, 1},
  };
  return table;
}

const MaterialParameter* find_material_parameter(const std::string& name) {
  for (const MaterialParameter& p : material_parameters())
    if (name == p.name) return &p;
  return nullptr;
}

}  // namespace hipr
