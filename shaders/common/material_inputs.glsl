// OpenPBR parameters of the glTF extension lobes at a surface point: the MaterialBlock factor
// times its texture (channels as glTF packs them; every texture with its own UV set and
// KHR_texture_transform). The BSDF calls these when it builds its lobes; each costs a texture
// lookup only when the material has that texture. Needs surface.glsl.
#ifndef HIPR_MATERIAL_INPUTS_GLSL
#define HIPR_MATERIAL_INPUTS_GLSL

// factor x texture channel `channel` (0..3), or the factor alone without a texture.
float material_scalar(float factor, uint texture, int channel, SurfaceHit hit) {
  texture = hipr_texture_slot(texture);
  return texture == kInvalidIndex ? factor : factor * sample_material_texture(texture, hit)[channel];
}

vec3 material_color(vec3 factor, uint texture, SurfaceHit hit) {
  texture = hipr_texture_slot(texture);
  return texture == kInvalidIndex ? factor : factor * sample_material_texture(texture, hit).rgb;
}

// transmission_weight x transmissionTexture.r
float material_transmission_weight(SurfaceHit hit) {
  return material_scalar(b_materials[hit.material].transmission_weight, b_materials[hit.material].transmission_texture, 0, hit);
}

// coat_weight x clearcoatTexture.r
float material_coat_weight(SurfaceHit hit) {
  return material_scalar(b_materials[hit.material].coat_weight, b_materials[hit.material].clearcoat_texture, 0, hit);
}

// coat_roughness x clearcoatRoughnessTexture.g
float material_coat_roughness(SurfaceHit hit) {
  return material_scalar(b_materials[hit.material].coat_roughness, b_materials[hit.material].clearcoat_roughness_texture, 1, hit);
}

// The coat's shading normal: clearcoatNormalTexture on the interpolated normal (glTF: without
// it the coat follows the geometry, not the base's normal map). Same side as hit.geometricNormal.
vec3 material_coat_normal(SurfaceHit hit) {
  const uint texture = hipr_normal_map_slot(b_materials[hit.material].clearcoat_normal_texture);
  if (texture == kInvalidIndex) return hit.vertexNormal;
  const vec3 front = hit.frontFacing ? hit.vertexNormal : -hit.vertexNormal;
  const vec3 n = apply_normal_map(texture, b_materials[hit.material].coat_normal_scale, hit, front);
  return hit.frontFacing ? n : -n;
}

// fuzz_color x sheenColorTexture.rgb (fuzz_weight is 1 for any glTF sheen, 0 without)
vec3 material_fuzz_color(SurfaceHit hit) {
  return material_color(b_materials[hit.material].fuzz_color, b_materials[hit.material].sheen_color_texture, hit);
}

// fuzz_roughness x sheenRoughnessTexture.a
float material_fuzz_roughness(SurfaceHit hit) {
  return material_scalar(b_materials[hit.material].fuzz_roughness, b_materials[hit.material].sheen_roughness_texture, 3, hit);
}

// specular_weight x specularTexture.a
float material_specular_weight(SurfaceHit hit) {
  return material_scalar(b_materials[hit.material].specular_weight, b_materials[hit.material].specular_texture, 3, hit);
}

// specular_color x specularColorTexture.rgb
vec3 material_specular_color(SurfaceHit hit) {
  return material_color(b_materials[hit.material].specular_color, b_materials[hit.material].specular_color_texture, hit);
}

// thin_film_weight x iridescenceTexture.r
float material_thin_film_weight(SurfaceHit hit) {
  return material_scalar(b_materials[hit.material].thin_film_weight, b_materials[hit.material].iridescence_texture, 0, hit);
}

// Thin-film thickness in nanometres: mix(thin_film_thickness_min, thin_film_thickness,
// iridescenceThicknessTexture.g), or thin_film_thickness without the texture.
float material_thin_film_thickness(SurfaceHit hit) {
  const float thickest = b_materials[hit.material].thin_film_thickness;
  const uint texture = hipr_texture_slot(b_materials[hit.material].iridescence_thickness_texture);
  if (texture == kInvalidIndex) return thickest;
  return mix(b_materials[hit.material].thin_film_thickness_min, thickest, sample_material_texture(texture, hit).g);
}

struct MaterialAnisotropy {
  float strength;   // specular_anisotropy x anisotropyTexture.b, in [0, 1]
  vec3 direction;   // world space, unit, in the plane of hit.shadingNormal: the direction of
                    // larger roughness, already turned by specular_rotation and the texture
};

// KHR_materials_anisotropy: direction = rotate(anisotropyTexture.rg * 2 - 1, specular_rotation)
// in the (tangent, bitangent) frame; (1, 0) without a texture.
MaterialAnisotropy material_anisotropy(SurfaceHit hit) {
  MaterialAnisotropy a;
  a.strength = b_materials[hit.material].specular_anisotropy;
  vec2 d = vec2(1.0, 0.0);
  const uint texture = hipr_texture_slot(b_materials[hit.material].anisotropy_texture);
  if (texture != kInvalidIndex) {
    const vec3 t = sample_material_texture(texture, hit).rgb;
    d = t.xy * 2.0 - 1.0;
    a.strength *= t.z;
    d = dot(d, d) > 1e-12 ? normalize(d) : vec2(1.0, 0.0);
  }
  const float angle = b_materials[hit.material].specular_rotation;
  d = vec2(cos(angle) * d.x - sin(angle) * d.y, sin(angle) * d.x + cos(angle) * d.y);
  const vec3 front = hit.frontFacing ? hit.vertexNormal : -hit.vertexNormal;
  const vec3 bitangent = cross(front, hit.tangent.xyz) * (hit.tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 w = hit.tangent.xyz * d.x + bitangent * d.y;
  w -= hit.shadingNormal * dot(hit.shadingNormal, w);
  a.direction = dot(w, w) > 1e-12 ? normalize(w) : vec3(0.0);
  if (dot(w, w) <= 1e-12) a.strength = 0.0;  // no tangent frame here: isotropic
  return a;
}

#endif
