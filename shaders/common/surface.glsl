// Everything known about a surface point after a ray hit: geometry from the vertex buffers in
// world space, and the material with its textures applied.
#ifndef HIPR_SURFACE_GLSL
#define HIPR_SURFACE_GLSL

struct SurfaceHit {
  vec3 position;
  vec3 geometricNormal;  // front side per glTF winding, unit
  vec3 shadingNormal;    // interpolated (and normal-mapped), unit, same side as geometricNormal
  vec2 uv;
  uint geometry;         // GeometryRecord index
  uint primitive;
  uint material;
  bool frontFacing;      // the incoming ray hit the front side
};

struct ShadingParams {
  BaseParams bsdf;
  vec3 emission;  // radiance leaving the front side (both sides if double-sided), nits
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
  if (normalTexture != kInvalidIndex) {
    const vec4 t = b_tangents[v.x] * b0 + b_tangents[v.y] * bary.x + b_tangents[v.z] * bary.y;
    vec3 tangent = mat3(objectToWorld) * t.xyz;
    tangent = tangent - ns * dot(ns, tangent);
    if (dot(tangent, tangent) > 1e-12) {
      tangent = normalize(tangent);
      const vec3 bitangent = cross(ns, tangent) * (t.w < 0.0 ? -1.0 : 1.0);
      vec3 local = sample_texture(normalTexture, hit.uv).xyz * 2.0 - 1.0;
      local.xy *= b_materials[hit.material].normal_scale;
      const vec3 mapped = tangent * local.x + bitangent * local.y + ns * local.z;
      if (dot(mapped, mapped) > 1e-12) ns = normalize(mapped);
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

vec3 material_emission(uint material, vec2 uv) {
  vec3 e = b_materials[material].emission_color * b_materials[material].emission_luminance;
  const uint texture = b_materials[material].emission_texture;
  if (texture != kInvalidIndex && max3(e) > 0.0) e *= sample_texture(texture, uv).rgb;
  return e;
}

ShadingParams shading_params(SurfaceHit hit) {
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
  s.bsdf.baseColor = baseColor * b_materials[material].base_weight;
  s.bsdf.metalness = clamp(metalness, 0.0, 1.0);
  s.bsdf.specularColor = b_materials[material].specular_color;
  s.bsdf.specularWeight = b_materials[material].specular_weight;
  s.bsdf.specularIor = max(b_materials[material].specular_ior, 1.0);
  s.bsdf.alpha = ggx_alpha(clamp(roughness, 0.0, 1.0));
  s.doubleSided = (b_materials[material].flags & kMaterialDoubleSided) != 0u;
  s.emission = (hit.frontFacing || s.doubleSided) ? material_emission(material, hit.uv) : vec3(0.0);
  return s;
}

#endif
