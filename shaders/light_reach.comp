#version 460
// HiPR stage 1 for punctual lights an edit changed (moved, re-aimed, its range, cone, type,
// colour or intensity): a light is no G-buffer record, so mark_active.comp cannot see where it
// changes the image. Here the surface each pixel shows (the ray through its centre, as
// visibility.comp casts it) is lit by every changed light before and after the edit, shadow ray
// included; the light's direct contribution toward the camera (BSDF x cosine x what arrives,
// range window and cone included) is compared between the two states. A pixel either state
// reaches makes its tile active and adds 1 + kReachScoreScale x r^2 to the tile's change score,
// r being the change of direct light relative to the pixel's new value (the shown value plus the
// change), at most 1: relMSE weighs a pixel's error by its value, and shadows that moved or surfaces
// newly lit or darkened (r = 1) come before the slow falloff over a wide floor.
// Shadow rays of both states go through the scene as it is now (an edit that also moved geometry
// has it in E, where mark_active.comp finds it). Light arriving through other surfaces (bounces,
// glass) is stage 2's to discover from the reached tiles.
// Reads: TLAS and scene buffers, the G-buffer, the changed lights, the display.
// Writes: kTileActive | kTileScored into the tile flags, the tile change score.
#extension GL_GOOGLE_include_directive : require
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/scene_bindings.glsl"
#include "shared/bindings/visibility.h"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"
#include "common/sampling.glsl"
#include "common/ray_offset.glsl"
#include "common/textures.glsl"
#include "bsdf/bsdf.glsl"
#include "common/surface.glsl"
#include "common/cutout.glsl"
#include "common/scene_trace.glsl"
#include "common/material_inputs.glsl"
#include "common/dispersion.glsl"
#include "common/shading.glsl"
#include "common/environment.glsl"
#include "common/lights.glsl"

layout(scalar, binding = kReachGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kReachLights) readonly buffer ReachLights { Light b_reach_lights[]; };
layout(scalar, binding = kReachDisplay) readonly buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kReachTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kReachTileChange) buffer TileChange { uint b_tile_change[]; };
// u_lights changed lights: b_reach_lights[i] before the edit, b_reach_lights[u_lights + i] after.
layout(push_constant) uniform Push { uint u_lights; };

// What `light` would add to the pixel unshadowed: its direct radiance toward the camera (0 out
// of range or cone), and the shadow ray that decides it. `lit` tells whether its light may get to
// the surface at all: it arrives, on the camera's side of it or through a BSDF that passes it on
// (a mirror or a pane of glass shows the change only by what it reflects, but is lit all the
// same).
struct Arrival {
  bool lit;
  vec3 radiance;
  vec3 origin, toward;
  float tMax;
};

Arrival arrival_from(Light light, SurfaceHit surface, BsdfPoint bsdf, vec3 wo) {
  Arrival a;
  a.lit = false;
  a.radiance = vec3(0.0);
  vec3 direction, arriving;
  float distance = kFloatMax;
  if (light.type == kLightDirectional) {
    direction = -light.direction;
    arriving = light.intensity;
  } else if (!point_light_arrival(light, surface.position, direction, distance, arriving)) {
    return a;
  }
  if (!(max3(arriving) > 0.0)) return a;
  const vec3 f = bsdf_eval(bsdf, direction);
  const bool cameraSide = dot(direction, surface.geometricNormal) * dot(wo, surface.geometricNormal) > 0.0;
  if (!(max3(f) > 0.0) && !cameraSide) return a;
  const vec3 side = dot(direction, surface.geometricNormal) >= 0.0 ? surface.geometricNormal : -surface.geometricNormal;
  a.origin = offset_ray_origin(surface.position, side);
  a.tMax = kFloatMax;
  a.toward = direction;
  if (distance < kFloatMax) {
    const vec3 toLight = surface.position + direction * distance - a.origin;
    a.tMax = length(toLight);
    if (!(a.tMax > 0.0)) return a;
    a.toward = toLight / a.tMax;
    a.tMax *= 0.99999;
  }
  a.lit = true;
  a.radiance = max(f, vec3(0.0)) * arriving;
  return a;
}

// Whether two states of a light cast the same shadow ray from a surface: the same kind at the
// same place (point, spot) or travelling the same way (directional). An edit of the colour,
// intensity, range, cone or aim alone leaves the shadows as they were: one ray tells both.
bool same_shadow_ray(Light before, Light after) {
  return before.type == after.type &&
         (before.type == kLightDirectional ? before.direction == after.direction : before.position == after.position);
}

void main() {
  const uint index = dispatch_index();
  if (u_lights == 0u || index >= u_frame.width * u_frame.height) return;  // no light: a warm-up
  // Background: a punctual light changes nothing there.
  if (b_gbuffer[index].record == kInvalidIndex) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const vec3 ray = pixel_centre_ray(pixel);
  RayHit hit;
  if (!trace_closest(u_frame.cameraPosition, ray, 3.0e38, hit)) return;
  const SurfaceHit surface =
      make_surface_hit(hit.record, hit.primitive, hit.barycentrics, hit.objectToWorld, hit.worldToObject, ray);
  const vec3 wo = -ray;
  const ShadingParams shading = shading_params(surface, wo, kNoChannel);
  const BsdfPoint bsdf = bsdf_point(shading.bsdf, BsdfFrame(surface.shadingNormal, surface.geometricNormal, shading.tangent), wo);

  bool anyReached = false;
  vec3 change = vec3(0.0);
  for (uint i = 0u; i < min(u_lights, kMaxReachLights); ++i) {
    const Light lightBefore = b_reach_lights[i], lightAfter = b_reach_lights[u_lights + i];
    const Arrival before = arrival_from(lightBefore, surface, bsdf, wo);
    const Arrival after = arrival_from(lightAfter, surface, bsdf, wo);
    // Reached: lit and unblocked (0 where shadowed).
    const bool blockedBefore = before.lit && trace_occluded(before.origin, before.toward, before.tMax);
    const bool blockedAfter = after.lit && (before.lit && same_shadow_ray(lightBefore, lightAfter)
                                                ? blockedBefore
                                                : trace_occluded(after.origin, after.toward, after.tMax));
    const bool reachedBefore = before.lit && !blockedBefore, reachedAfter = after.lit && !blockedAfter;
    anyReached = anyReached || reachedBefore || reachedAfter;
    change += (reachedAfter ? after.radiance : vec3(0.0)) - (reachedBefore ? before.radiance : vec3(0.0));
  }
  if (!anyReached) return;
  // The pixel's value after the edit, as far as the screen and the direct light tell.
  const float delta = abs(luminance(change));
  const float shown = max(luminance(b_display[index].shown), 0.0);
  const float now = max(shown + luminance(change), delta);
  const float r = now > 0.0 && delta < 3.0e38 ? min(delta / now, 1.0) : 0.0;
  const uint tile = tile_of_pixel(pixel);
  atomicOr(b_tile_flags[tile], kTileActive | kTileScored);
  atomicAdd(b_tile_change[tile], 1u + uint(kReachScoreScale * r * r + 0.5));
}
