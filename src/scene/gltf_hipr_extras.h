#pragma once
// What hipr keeps in glTF `extras` when glTF itself cannot say it (written by save_scene, read
// back by the loader after the glTF mapping):
//   material.extras.hipr_openpbr   {"coat_darkening": 0.3, "base_color": [r, g, b], ...}
//       OpenPBR parameters (material_parameter_names()) whose value differs from what the
//       material's glTF fields map to (gltf_material_table.cpp): numbers for scalars, arrays of
//       three for colours, in the units of MaterialParameters.
//   extras.hipr_default_material    the same, for glTF's default material (primitives without one)
//   light.extras.hipr_light         {"color": [r, g, b], "intensity": I}: a KHR_lights_punctual
//       light whose colour exceeds glTF's [0, 1] (the glTF fields hold colour / max and
//       intensity x max, the same light for other viewers)
//   camera.extras.hipr_lens         {"aperture_radius": R, "focus_distance": D}: the camera's
//       thin lens (glTF cameras are pinholes), written when the lens is open
// Anything malformed under these keys is an InputError, as any other bad input.
#include <tiny_gltf.h>

#include <string>

#include "hipr/scene.h"

namespace hipr::gltf {

inline constexpr const char* kOpenPbrExtras = "hipr_openpbr";
inline constexpr const char* kDefaultMaterialExtras = "hipr_default_material";
inline constexpr const char* kLightExtras = "hipr_light";
inline constexpr const char* kLensExtras = "hipr_lens";

// Applies extras[key] (when `extras` is an object holding `key`) to `params`; `what` names the
// owner in error messages.
void apply_openpbr_extras(const tinygltf::Value& extras, const char* key,
                          MaterialParameters& params, const std::string& what);

// Applies extras.hipr_lens (when present) to `camera`.
void apply_lens_extras(const tinygltf::Value& extras, Camera& camera, const std::string& what);

// Applies extras.hipr_light (when present) to `light`.
void apply_light_extras(const tinygltf::Value& extras, PunctualLight& light,
                        const std::string& what);

}  // namespace hipr::gltf
