#version 460
// HiPR stage 1: one primary ray through every pixel centre.
// Reads: TLAS (or the software BVH), FrameParams, and the scene buffers the opacity cutout needs (geometry records,
// materials, UVs, textures). Writes: the G-buffer (record hit, camera-space depth, the
// triangle's geometric normal) per pixel.
#extension GL_GOOGLE_include_directive : require
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/scene_bindings.glsl"
#include "shared/bindings/visibility.h"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"
#include "common/textures.glsl"
#include "common/cutout.glsl"
#include "common/scene_trace.glsl"
#include "common/octahedral.glsl"

layout(scalar, binding = kVisibilityGBuffer) writeonly buffer GBuffer { GBufferTexel b_gbuffer[]; };

// The hit triangle's normal in world space, packed (kNormalUnknown for a degenerate triangle).
uint geometric_normal(RayHit hit) {
  const uvec3 v = triangle_vertices(b_geometries[hit.record], hit.primitive);
  const vec3 n = world_face_normal(b_positions[v.x], b_positions[v.y], b_positions[v.z], hit.worldToObject);
  return dot(n, n) > 0.0 ? pack_normal(normalize(n)) : kNormalUnknown;
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_frame.width * u_frame.height) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const vec3 direction = pixel_centre_ray(pixel);
  GBufferTexel texel = GBufferTexel(kInvalidIndex, 3.0e38, kNormalUnknown);
  RayHit hit;
  if (trace_closest(u_frame.cameraPosition, direction, 3.0e38, hit)) {
    texel.record = hit.record;
    texel.depth = hit.t * dot(direction, u_frame.cameraForward);
    texel.normal = geometric_normal(hit);
  }
  b_gbuffer[index] = texel;
}
