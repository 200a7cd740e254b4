// Vertex data of one triangle from the shared buffers (needs scene_bindings.glsl).
#ifndef HIPR_VERTICES_GLSL
#define HIPR_VERTICES_GLSL

// Vertex indices of a primitive, already offset into the shared vertex buffers.
uvec3 triangle_vertices(GeometryRecord g, uint primitive) {
  const uint base = g.firstIndex + 3u * primitive;
  return uvec3(b_indices[base], b_indices[base + 1u], b_indices[base + 2u]) + g.vertexOffset;
}

// Both UV sets at once (TEXCOORD_0 in xy, TEXCOORD_1 in zw): one interpolation for either.
vec4 interpolate_uv(uvec3 v, vec2 bary) {
  return b_uvs[v.x] * (1.0 - bary.x - bary.y) + b_uvs[v.y] * bary.x + b_uvs[v.z] * bary.y;
}

// The triangle's geometric normal in world space, not normalised (zero where the triangle is
// degenerate). Normals transform with the inverse transpose: n_world = n_object * mat3(worldToObject).
vec3 world_face_normal(vec3 p0, vec3 p1, vec3 p2, mat4x3 worldToObject) {
  return transpose(mat3(worldToObject)) * cross(p1 - p0, p2 - p0);
}

#endif
