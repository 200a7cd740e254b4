// HiPR stage 2: project path vertices into the camera and grow the weight of the tile they
// land in, if the G-buffer shows that very point there (depth test). Needs scene_bindings.glsl and
// cutout.glsl.
#ifndef HIPR_DISCOVERY_GLSL
#define HIPR_DISCOVERY_GLSL

layout(scalar, binding = kTraceGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kTraceChangedRecords) readonly buffer Changed { uint b_changed_records[]; };
// Fixed-point (kWeightScale units) 64-bit sums: integer atomics make W(T) independent of the
// order in which threads add, so the schedule is deterministic.
layout(scalar, binding = kTraceTileWeights) buffer TileWeights { uint64_t b_tile_weights[]; };

float discovery_lobe_weight(uint lobe) { return u_frame.wLobe[min(lobe, 3u)]; }

// Pinhole projection P(x) of the paper: principal point at the image centre, square pixels.
// Returns false when x is behind the camera or outside the frame.
bool project_to_pixel(vec3 x, out uvec2 pixel, out float depth) {
  const vec3 d = x - u_frame.cameraPosition;
  depth = dot(d, u_frame.cameraForward);
  if (depth <= 0.0) return false;
  const float sx = dot(d, u_frame.cameraRight) / (depth * u_frame.tanHalfFovY * u_frame.aspect);
  const float sy = dot(d, u_frame.cameraUp) / (depth * u_frame.tanHalfFovY);
  const vec2 p = vec2((sx + 1.0) * 0.5 * float(u_frame.width), (1.0 - sy) * 0.5 * float(u_frame.height));
  if (!(p.x >= 0.0 && p.y >= 0.0 && p.x < float(u_frame.width) && p.y < float(u_frame.height))) return false;
  pixel = uvec2(p);
  return true;
}

void discover_vertex(vec3 x, float weight) {
  if (!(weight > 0.0) || isinf(weight)) return;
  uvec2 pixel;
  float depth;
  if (!project_to_pixel(x, pixel, depth)) return;
  const float seen = b_gbuffer[pixel.y * u_frame.width + pixel.x].depth;
  if (abs(depth - seen) > u_frame.depthEpsilon * seen) return;  // hidden from the camera
  const uint tile = tile_of_pixel(pixel);
  atomicAdd(b_tile_weights[tile], uint64_t(min(weight, 1.0e6) * kWeightScale + 0.5));
  atomicOr(b_tile_flags[tile], kTileDiscovered);
}

// The record a shadow ray hits first, or kInvalidIndex when it is unblocked.
uint closest_blocker(vec3 origin, vec3 direction, float tMax) {
  RayHit hit;
  return trace_closest(origin, direction, tMax, hit) ? hit.record : kInvalidIndex;
}

#endif
