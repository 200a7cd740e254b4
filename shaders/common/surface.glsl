// Everything known about a surface point after a ray hit: geometry from the vertex buffers in
// world space, and the material's emission (shading.glsl builds the BSDF parameters).
#ifndef HIPR_SURFACE_GLSL
#define HIPR_SURFACE_GLSL

#include "features.glsl"
#include "vertices.glsl"

struct SurfaceHit {
  vec3 position;
  vec3 geometricNormal;  // front side per glTF winding, unit
  vec3 shadingNormal;    // interpolated (and normal-mapped), unit, same side as geometricNormal
  vec3 vertexNormal;     // interpolated, before normal mapping, same side as geometricNormal
  vec4 tangent;          // xyz: unit, orthogonal to vertexNormal (0 without normal map or anisotropy); w: bitangent sign
  vec4 uvs;              // TEXCOORD_0 in xy, TEXCOORD_1 in zw
  uint geometry;         // GeometryRecord index
  uint primitive;
  uint material;
  bool frontFacing;      // the incoming ray hit the front side
};

// A material texture at the hit: the texture's own UV set and transform (textures.glsl).
vec4 sample_material_texture(uint textureSlot, SurfaceHit hit) { return sample_texture(textureSlot, hit.uvs); }

// Tangent-space normal map `texture` (scale as glTF's normalTexture.scale) applied to the unit
// normal `n`, in the hit's tangent frame; `n` itself when the frame is degenerate. `n` must be
// on the side the tangent frame was built for (the front side, glTF's bitangent sign).
vec3 apply_normal_map(uint texture, float scale, SurfaceHit hit, vec3 n) {
  vec3 tangent = hit.tangent.xyz - n * dot(n, hit.tangent.xyz);
  if (dot(tangent, tangent) <= 1e-12) return n;
  tangent = normalize(tangent);
  const vec3 bitangent = cross(n, tangent) * (hit.tangent.w < 0.0 ? -1.0 : 1.0);
  vec3 local = sample_material_texture(texture, hit).xyz * 2.0 - 1.0;
  local.xy *= scale;
  const vec3 mapped = tangent * local.x + bitangent * local.y + n * local.z;
  return dot(mapped, mapped) > 1e-12 ? normalize(mapped) : n;
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
  vec3 ng = world_face_normal(p0, p1, p2, worldToObject);
  ng = dot(ng, ng) > 0.0 ? normalize(ng) : vec3(0.0, 1.0, 0.0);
  vec3 ns = transpose(mat3(worldToObject)) * (b_normals[v.x] * b0 + b_normals[v.y] * bary.x + b_normals[v.z] * bary.y);
  ns = dot(ns, ns) > 0.0 ? normalize(ns) : ng;
  hit.uvs = interpolate_uv(v, bary);
  // Only normal maps and anisotropy need the tangent frame: other hits skip its three loads.
  hit.tangent = vec4(0.0, 0.0, 0.0, 1.0);
  if (hipr_normal_map_slot(b_materials[hit.material].normal_texture) != kInvalidIndex ||
      hipr_normal_map_slot(b_materials[hit.material].clearcoat_normal_texture) != kInvalidIndex ||
      (HIPR_FEATURE_ANISOTROPY != 0 && b_materials[hit.material].specular_anisotropy > 0.0)) {
    const vec4 t = b_tangents[v.x] * b0 + b_tangents[v.y] * bary.x + b_tangents[v.z] * bary.y;
    vec3 tangent = mat3(objectToWorld) * t.xyz;
    tangent = tangent - ns * dot(ns, tangent);
    hit.tangent = vec4(dot(tangent, tangent) > 1e-12 ? normalize(tangent) : vec3(0.0), t.w < 0.0 ? -1.0 : 1.0);
  }

  // Materials are read field by field: copying the whole block costs loads on CPU devices.
  const uint normalTexture = hipr_normal_map_slot(b_materials[hit.material].normal_texture);
  hit.vertexNormal = ns;
  if (normalTexture != kInvalidIndex) ns = apply_normal_map(normalTexture, b_materials[hit.material].normal_scale, hit, ns);

  hit.frontFacing = dot(ng, rayDirection) < 0.0;
  // Shade on the side the ray arrived from; the shading normal follows the geometric one.
  if (!hit.frontFacing) {
    ng = -ng;
    ns = -ns;
    hit.vertexNormal = -hit.vertexNormal;
  }
  if (dot(ns, ng) < 0.0) ns = normalize(ns - ng * (1.01 * dot(ns, ng)));
  hit.geometricNormal = ng;
  hit.shadingNormal = ns;
  return hit;
}

// Emitted radiance toward a direction at cosine mu_o from the normal, after the coat and fuzz.
// uvSets as in SurfaceHit.uvs (light sampling has no SurfaceHit).
vec3 material_emission(uint material, vec4 uvSets, float mu_o) {
  if (HIPR_FEATURE_EMISSION == 0) return vec3(0.0);
  vec3 e = b_materials[material].emission_color * b_materials[material].emission_luminance;
  if (max3(e) <= 0.0) return vec3(0.0);
  const uint texture = hipr_texture_slot(b_materials[material].emission_texture);
  if (texture != kInvalidIndex) e *= sample_texture(texture, uvSets).rgb;
  const float coat = HIPR_FEATURE_COAT != 0 ? b_materials[material].coat_weight : 0.0;
  const float fuzz = HIPR_FEATURE_FUZZ != 0 ? b_materials[material].fuzz_weight : 0.0;
  if (coat > 0.0 || fuzz > 0.0)
    e *= layers_emission_scale(clamp(coat, 0.0, 1.0), b_materials[material].coat_color,
                               ggx_alpha(clamp(b_materials[material].coat_roughness, 0.0, 1.0)),
                               max(b_materials[material].coat_ior, 1.0), clamp(fuzz, 0.0, 1.0),
                               b_materials[material].fuzz_roughness, clamp(mu_o, 0.0, 1.0));
  return e;
}

#endif
