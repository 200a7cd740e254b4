// Everything known about a surface point after a ray hit: geometry from the vertex buffers in
// world space, and the material with its textures applied.
#ifndef HIPR_SURFACE_GLSL
#define HIPR_SURFACE_GLSL

#include "features.glsl"

struct SurfaceHit {
  vec3 position;
  vec3 geometricNormal;  // front side per glTF winding, unit
  vec3 shadingNormal;    // interpolated (and normal-mapped), unit, same side as geometricNormal
  vec3 tangent;          // anisotropy direction (specular_rotation applied); zero when isotropic
  vec2 uv;
  uint geometry;         // GeometryRecord index
  uint primitive;
  uint material;
  bool frontFacing;      // the incoming ray hit the front side
};

struct ShadingParams {
  OpenPbrParams bsdf;
  vec3 emission;    // radiance toward wo leaving the front side (both sides if double-sided), nits
  vec3 absorption;  // Beer-Lambert coefficient (1/m) of the medium behind the surface; 0 for none
  bool doubleSided;
};

// Vertex indices of a primitive, already offset into the shared vertex buffers.
uvec3 triangle_vertices(GeometryRecord g, uint primitive) {
  const uint base = g.firstIndex + 3u * primitive;
  return uvec3(b_indices[base], b_indices[base + 1u], b_indices[base + 2u]) + g.vertexOffset;
}

vec2 interpolate_uv(uvec3 v, vec2 bary) {
  return b_uvs[v.x] * (1.0 - bary.x - bary.y) + b_uvs[v.y] * bary.x + b_uvs[v.z] * bary.y;
}

SurfaceHit make_surface_hit(uint geometry, uint primitive, vec2 bary, mat4x3 objectToWorld,
                            mat4x3 worldToObject, vec3 rayDirection) {
  const GeometryRecord g = b_geometries[geometry];
  const uvec3 v = triangle_vertices(g, primitive);
  const vec3 p0 = b_positions[v.x], p1 = b_positions[v.y], p2 = b_positions[v.z];
  const float b0 = 1.0 - bary.x - bary.y;

  SurfaceHit hit;
  hit.geometry = geometry;
  hit.primitive = primitive;
  hit.material = g.materialIndex;
  // Interpolating in object space, then transforming, keeps the point on the triangle exactly.
  hit.position = objectToWorld * vec4(p0 * b0 + p1 * bary.x + p2 * bary.y, 1.0);
  // Normals transform with the inverse transpose: n_world = n_object * mat3(worldToObject).
  const mat3 normalMatrix = transpose(mat3(worldToObject));
  vec3 ng = normalMatrix * cross(p1 - p0, p2 - p0);
  ng = dot(ng, ng) > 0.0 ? normalize(ng) : vec3(0.0, 1.0, 0.0);
  vec3 ns = normalMatrix * (b_normals[v.x] * b0 + b_normals[v.y] * bary.x + b_normals[v.z] * bary.y);
  ns = dot(ns, ns) > 0.0 ? normalize(ns) : ng;
  hit.uv = interpolate_uv(v, bary);

  // Materials are read field by field: copying the whole block costs loads on CPU devices.
  const uint normalTexture = b_materials[hit.material].normal_texture;
  const float anisotropy = HIPR_FEATURE_ANISOTROPY != 0 ? b_materials[hit.material].specular_anisotropy : 0.0;
  hit.tangent = vec3(0.0);
  if (normalTexture != kInvalidIndex || anisotropy > 0.0) {
    const vec4 t = b_tangents[v.x] * b0 + b_tangents[v.y] * bary.x + b_tangents[v.z] * bary.y;
    vec3 tangent = mat3(objectToWorld) * t.xyz;
    tangent = tangent - ns * dot(ns, tangent);
    if (dot(tangent, tangent) > 1e-12) {
      tangent = normalize(tangent);
      const vec3 bitangent = cross(ns, tangent) * (t.w < 0.0 ? -1.0 : 1.0);
      if (normalTexture != kInvalidIndex) {
        vec3 local = sample_texture(normalTexture, hit.uv).xyz * 2.0 - 1.0;
        local.xy *= b_materials[hit.material].normal_scale;
        const vec3 mapped = tangent * local.x + bitangent * local.y + ns * local.z;
        if (dot(mapped, mapped) > 1e-12) ns = normalize(mapped);
      }
      if (anisotropy > 0.0) {
        // specular_rotation turns the anisotropy direction from the tangent toward the bitangent.
        const float angle = b_materials[hit.material].specular_rotation;
        hit.tangent = tangent * cos(angle) + bitangent * sin(angle);
      }
    }
  }

  hit.frontFacing = dot(ng, rayDirection) < 0.0;
  // Shade on the side the ray arrived from; the shading normal follows the geometric one.
  if (!hit.frontFacing) {
    ng = -ng;
    ns = -ns;
  }
  if (dot(ns, ng) < 0.0) ns = normalize(ns - ng * (1.01 * dot(ns, ng)));
  hit.geometricNormal = ng;
  hit.shadingNormal = ns;
  return hit;
}

// Emitted radiance toward a direction at cosine mu_o from the normal, after the coat and fuzz.
vec3 material_emission(uint material, vec2 uv, float mu_o) {
  vec3 e = b_materials[material].emission_color * b_materials[material].emission_luminance;
  if (max3(e) <= 0.0) return vec3(0.0);
  const uint texture = b_materials[material].emission_texture;
  if (texture != kInvalidIndex) e *= sample_texture(texture, uv).rgb;
  const float coat = HIPR_FEATURE_COAT != 0 ? b_materials[material].coat_weight : 0.0;
  const float fuzz = HIPR_FEATURE_FUZZ != 0 ? b_materials[material].fuzz_weight : 0.0;
  if (coat > 0.0 || fuzz > 0.0)
    e *= layers_emission_scale(clamp(coat, 0.0, 1.0), b_materials[material].coat_color,
                               ggx_alpha(clamp(b_materials[material].coat_roughness, 0.0, 1.0)),
                               max(b_materials[material].coat_ior, 1.0), clamp(fuzz, 0.0, 1.0),
                               b_materials[material].fuzz_roughness, clamp(mu_o, 0.0, 1.0));
  return e;
}

// OpenPBR parameters at the hit, seen from the side the ray arrived on: a ray inside a
// transmissive solid sees the inverse index and no coat (the coat is on the outside).
ShadingParams shading_params(SurfaceHit hit, vec3 wo) {
  const uint material = hit.material;
  ShadingParams s;
  vec3 baseColor = b_materials[material].base_color;
  const uint baseTexture = b_materials[material].base_color_texture;
  if (baseTexture != kInvalidIndex) baseColor *= sample_texture(baseTexture, hit.uv).rgb;
  float metalness = b_materials[material].base_metalness;
  float roughness = b_materials[material].specular_roughness;
  const uint mrTexture = b_materials[material].metallic_roughness_texture;
  if (mrTexture != kInvalidIndex) {
    const vec4 mr = sample_texture(mrTexture, hit.uv);  // glTF packing: G roughness, B metalness
    roughness *= mr.g;
    metalness *= mr.b;
  }
  const uint flags = b_materials[material].flags;
  const bool thin = (flags & kMaterialThinWalled) != 0u;
  // Features the kernel was compiled without become constants here (features.glsl).
  OpenPbrParams p;
  p.baseColor = baseColor * b_materials[material].base_weight;
  p.metalness = HIPR_FEATURE_METAL != 0 ? clamp(metalness, 0.0, 1.0) : 0.0;
  p.diffuseRoughness =
      HIPR_FEATURE_DIFFUSE_ROUGHNESS != 0 ? clamp(b_materials[material].base_diffuse_roughness, 0.0, 1.0) : 0.0;
  p.specularColor = b_materials[material].specular_color;
  p.specularWeight = b_materials[material].specular_weight;
  p.alpha = ggx_alpha_anisotropic(clamp(roughness, 0.0, 1.0),
                                  HIPR_FEATURE_ANISOTROPY != 0 ? b_materials[material].specular_anisotropy : 0.0);
  const float ior = ior_with_specular_weight(max(b_materials[material].specular_ior, 1.0), p.specularWeight);
  p.eta = HIPR_FEATURE_SPECULAR != 0 || HIPR_FEATURE_TRANSMISSION != 0 ? ((thin || hit.frontFacing) ? ior : 1.0 / ior) : 1.0;
  p.transmission = HIPR_FEATURE_TRANSMISSION != 0 ? clamp(b_materials[material].transmission_weight, 0.0, 1.0) : 0.0;
  const vec3 transmissionColor = b_materials[material].transmission_color;
  const float depth = b_materials[material].transmission_depth;
  const bool volume = !thin && depth > 0.0 && p.transmission > 0.0;
  p.transmissionColor = volume ? vec3(1.0) : transmissionColor;
  s.absorption = volume ? -log(clamp(transmissionColor, vec3(1.0e-6), vec3(1.0))) / depth : vec3(0.0);
  p.thinWalled = thin;
  p.subsurface = HIPR_FEATURE_SUBSURFACE != 0 ? clamp(b_materials[material].subsurface_weight, 0.0, 1.0) : 0.0;
  p.subsurfaceColor = b_materials[material].subsurface_color;
  const bool inside = !thin && !hit.frontFacing && p.transmission > 0.0;
  p.coat = HIPR_FEATURE_COAT != 0 && !inside ? clamp(b_materials[material].coat_weight, 0.0, 1.0) : 0.0;
  p.coatColor = b_materials[material].coat_color;
  p.coatAlpha = ggx_alpha(clamp(b_materials[material].coat_roughness, 0.0, 1.0));
  p.coatEta = max(b_materials[material].coat_ior, 1.0);
  p.coatDarkening = clamp(b_materials[material].coat_darkening, 0.0, 1.0);
  p.fuzz = HIPR_FEATURE_FUZZ != 0 && !inside ? clamp(b_materials[material].fuzz_weight, 0.0, 1.0) : 0.0;
  p.fuzzColor = b_materials[material].fuzz_color;
  p.fuzzRoughness = clamp(b_materials[material].fuzz_roughness, 0.0, 1.0);
  p.thinFilm = HIPR_FEATURE_THIN_FILM != 0 ? clamp(b_materials[material].thin_film_weight, 0.0, 1.0) : 0.0;
  p.thinFilmThickness = 1000.0 * max(b_materials[material].thin_film_thickness, 0.0);  // OpenPBR: micrometres
  p.thinFilmIor = max(b_materials[material].thin_film_ior, 1.0);
  s.bsdf = p;
  s.doubleSided = (flags & kMaterialDoubleSided) != 0u;
  s.emission = (hit.frontFacing || s.doubleSided) ? material_emission(material, hit.uv, dot(hit.geometricNormal, wo)) : vec3(0.0);
  return s;
}

#endif
