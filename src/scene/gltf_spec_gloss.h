#pragma once
// KHR_materials_pbrSpecularGlossiness (older assets) as metal/rough OpenPBR parameters, by the
// conversion Khronos' tools use: the metalness that explains the diffuse and specular colours
// best (solved per colour), the base colour blended from both, roughness = 1 - glossiness. With
// textures the conversion runs per texel into two new images (base colour with alpha, and a
// metallic-roughness image), sampled as the diffuse texture is.
#include <tiny_gltf.h>

#include <string>

#include "hipr/material.h"
#include "scene/gltf_textures.h"

namespace hipr::gltf {

// The material's factors (map_material_factors): converted when it has no textures; with
// textures, 1s that the baked images multiply. Does nothing without the extension.
void apply_spec_gloss_factors(const tinygltf::Material& m, MaterialParameters& p);

// The material's textures, baked (convert_material). Does nothing without the extension or
// without its textures.
void apply_spec_gloss_textures(const tinygltf::Material& m, MaterialParameters& p,
                               TextureTable& textures, Scene& scene, const std::string& what);

}  // namespace hipr::gltf
