#version 460
// Path-tracing megakernel over a list of tiles.
// Reads:  scene buffers (geometry, materials, textures, lights, environment), the TLAS,
//         the tile list (tile ids in render order), the background-tile mask, the tile flags and
//         pixel-lead bits (which target a pixel's visit brings it to) and FrameParams.
// Writes: per-pixel accumulation (radiance sum, sum of squares, sample count), each light group's
//         share of the sum (HIPR_LIGHT_GROUPS > 0), the difference records (HIPR_DIFFERENCE 1: the
//         first samples' values and, after an edit, their differences from the old scene's; reads
//         the display's stale estimate for their weights) and the ray/sample counters.
// One invocation owns one pixel for the whole dispatch and adds `samplesPerPixel` samples (or,
// with a `sampleTarget`, what the pixel lacks of it) whose indices continue the pixel's count,
// so results never depend on tile order.
#extension GL_GOOGLE_include_directive : require
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

layout(local_size_x = 64) in;  // == kWorkgroupSize

#include "common/scene_bindings.glsl"
#include "shared/bindings/trace.h"

layout(scalar, binding = kTraceTileList) readonly buffer TileList { uint b_tiles[]; };
layout(scalar, binding = kTraceAccumulation) buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kTraceStats) buffer Stats { RenderStats b_stats; };
layout(scalar, binding = kTraceTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kTraceTileBackground) readonly buffer TileBackground { uint b_tile_background[]; };
layout(scalar, binding = kTracePixelLead) readonly buffer PixelLead { uint b_pixel_lead[]; };
layout(scalar, binding = kTraceGroupSums) buffer GroupSums { vec3 b_group_sums[]; };
layout(scalar, binding = kTraceMaterialGroups) readonly buffer MaterialGroups { uint b_material_groups[]; };

#include "common/rng.glsl"
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
#include "common/pixel_ray.glsl"
#include "common/lights.glsl"
#include "common/guiding.glsl"
#include "common/tile_pixels.glsl"

layout(push_constant, scalar) uniform Push { TracePush u_push; };

// Which estimators take part (a compile-time switch, so tests can check that each one alone
// converges to the same image): kLightSamplingMis, kLightSamplingBsdfOnly, kLightSamplingLightOnly.
// Stage 2 of HiPR: with HIPR_DISCOVERY 1 every secondary vertex that is visible in the frame
// adds weight to the tile it projects to (see shaders/common/discovery.glsl).
#ifndef HIPR_DISCOVERY
#define HIPR_DISCOVERY 0
#endif
#if HIPR_DISCOVERY
#include "common/discovery.glsl"
#endif

#ifndef HIPR_LIGHT_SAMPLING
#define HIPR_LIGHT_SAMPLING kLightSamplingMis
#endif

// Light groups (src/render/light_groups.h): how many groups' shares of the radiance are kept.
#ifndef HIPR_LIGHT_GROUPS
#define HIPR_LIGHT_GROUPS 0
#endif
#if HIPR_LIGHT_GROUPS > 0
vec3 g_sampleGroups[HIPR_LIGHT_GROUPS];  // the current sample's radiance by group (per invocation)
#endif

// The difference estimate (docs/method.md#the-difference-estimate): sample i < kDifferenceSamples
// of a pixel is kept, and compared with the kept sample i of the scene before the edit.
#ifndef HIPR_DIFFERENCE
#define HIPR_DIFFERENCE 0
#endif
#if HIPR_DIFFERENCE
layout(scalar, binding = kTraceDifference) buffer Difference { DifferenceRecord b_difference[]; };
layout(scalar, binding = kTraceDisplay) readonly buffer Display { DisplayTexel b_display[]; };
#include "common/difference.glsl"

// Sample `index` of the scene as it is now has `value`: compared with the old scene's sample
// `index` where the record holds it (the same random numbers drew both), then kept in its place.
void note_sample(inout DifferenceRecord record, uint index, vec3 value, uint valid, vec3 stale) {
  const vec3 fresh = half_precision(value);
  if (index < valid) {
    const vec3 old = record_vec3(record, 3u * index);
    const vec3 d = fresh - old;
    const vec3 w = relmse_weight(stale);
    set_record_vec3(record, kDifferenceSum, record_vec3(record, kDifferenceSum) + d);
    set_record_vec3(record, kDifferenceCross, record_vec3(record, kDifferenceCross) + w * d * (old - stale));
    set_record_vec3(record, kDifferenceOld, record_vec3(record, kDifferenceOld) + w * (old - stale) * (old - stale));
    set_record_value(record, kDifferenceSquares, record_value(record, kDifferenceSquares) + dot(w, d * d));
  }
  set_record_vec3(record, 3u * index, fresh);
}
#endif

// Weight of radiance found by BSDF sampling, given the light-sampling pdf of the same direction.
float bsdf_hit_weight(float bsdfPdf, float lightPdf) {
  if (HIPR_LIGHT_SAMPLING == kLightSamplingBsdfOnly) return 1.0;
  if (HIPR_LIGHT_SAMPLING == kLightSamplingLightOnly) return lightPdf > 0.0 ? 0.0 : 1.0;
  return power_heuristic(bsdfPdf, lightPdf);
}

// MIS weight for radiance found by BSDF sampling on an emissive triangle, from the vertex at
// `from` with shading normal `fromNormal` (light selection depends on where it is made).
float emitter_hit_weight(SurfaceHit surface, float distance, vec3 direction, float bsdfPdf, vec3 from,
                         vec3 fromNormal) {
  const uint lightOffset = b_geometries[surface.geometry].lightOffset;
  if (lightOffset == kInvalidIndex) return 1.0;  // not in the light table: BSDF sampling only
  const uint index = lightOffset + surface.primitive;
  const float cosAtLight = abs(dot(surface.geometricNormal, direction));
  const float lightPdf =
      light_selection_pdf(index, from, fromNormal) * triangle_light_pdf(b_lights[index], distance, cosAtLight);
  return bsdf_hit_weight(bsdfPdf, lightPdf);
}

// Ray origin just off the surface on the side `direction` leaves toward (transmission leaves
// through the back).
vec3 leave_surface(vec3 position, vec3 geometricNormal, vec3 direction) {
  return offset_ray_origin(position, dot(direction, geometricNormal) >= 0.0 ? geometricNormal : -geometricNormal);
}

// The density with which a path leaves a vertex in `direction`: the BSDF's, mixed with the
// guide's where it guides (one-sample MIS with the balance heuristic between the two). The
// guide counts only where the BSDF's sampling reaches too: a direction that the BSDF has a value
// for but never samples (light sampling alone finds what arrives there) would otherwise weigh
// f / guide density, unbounded; so both strategies keep the support BSDF sampling has alone.
float scatter_pdf(BsdfPoint bsdf, GuideSite site, vec3 direction) {
  const float bsdfPdf = bsdf_pdf(bsdf, direction);
  if (site.probability <= 0.0 || !(bsdfPdf > 0.0)) return bsdfPdf;
  return site.probability * guide_pdf(site, direction) + (1.0 - site.probability) * bsdfPdf;
}

// The next direction of a path: from the guide with the site's probability (u.x picks, u.yz
// place it), else from the BSDF (v). Weights are f |cos| over the mixed density; a delta event,
// which only the BSDF draws, is weighed by the chance that the BSDF drew it.
BsdfSample scatter_sample(BsdfPoint bsdf, GuideSite site, vec3 v, vec3 u) {
  if (site.probability <= 0.0) return bsdf_sample(bsdf, v);
  if (u.x < site.probability) {
    BsdfSample b;
    b.lobe = kLobeDiffuse;
    b.isDelta = false;
    float guidePdf;
    b.direction = guide_sample(site, u.yz, guidePdf);
    const float bsdfPdf = bsdf_pdf(bsdf, b.direction);
    b.pdf = site.probability * guidePdf + (1.0 - site.probability) * bsdfPdf;
    const vec3 f = bsdf_eval(bsdf, b.direction);
    if (!(bsdfPdf > 0.0) || !(b.pdf > 0.0) || max3(f) <= 0.0) {  // outside BSDF sampling's support
      b.pdf = 0.0;
      b.weight = vec3(0.0);
      return b;
    }
    b.weight = f / b.pdf;
    return b;
  }
  BsdfSample b = bsdf_sample(bsdf, v);
  if (b.pdf <= 0.0) return b;
  if (b.isDelta) {
    b.weight /= 1.0 - site.probability;
    return b;
  }
  const vec3 f = b.weight * b.pdf;
  b.pdf = site.probability * guide_pdf(site, b.direction) + (1.0 - site.probability) * b.pdf;
  b.weight = f / b.pdf;
  return b;
}

// What light sample `ls` brings to the surface through the BSDF: a shadow ray, and MIS against
// the BSDF's density where both could find it. Rays traced, by kind: x camera, y extension (a
// path's later segments), z shadow.
// Whether the shadow ray from the surface to light sample `ls` is free (counted in rays.z).
bool light_sample_visible(SurfaceHit surface, LightSample ls, float occlusionWeight, inout uvec3 rays) {
  const vec3 origin = leave_surface(surface.position, surface.geometricNormal, ls.direction);
  vec3 direction = ls.direction;
  float tMax = kFloatMax;
  if (ls.distance < kFloatMax) {
    // Aim at the light point lifted off its own surface, so the light never shadows itself.
    vec3 target = surface.position + ls.direction * ls.distance;
    if (!ls.isDelta) target = offset_ray_origin(target, ls.lightNormal);
    const vec3 toTarget = target - origin;
    tMax = length(toTarget);
    if (tMax <= 0.0) return false;
    direction = toTarget / tMax;
    tMax *= 0.99999;
  }
  rays.z += 1u;
#if HIPR_DISCOVERY
  // Stage 2: a shadow cast by a changed element makes the shadowed point's tile a priority.
  const uint blocker = closest_blocker(origin, direction, tMax);
  if (blocker != kInvalidIndex) {
    if ((b_changed_records[blocker] & ~kRecordViewDependent) != 0u) discover_vertex(surface.position, occlusionWeight * u_frame.wOcclusion);
    return false;
  }
  return true;
#else
  return !trace_occluded(origin, direction, tMax);
#endif
}

vec3 light_sample_contribution(SurfaceHit surface, BsdfPoint bsdf, GuideSite site, LightSample ls, float occlusionWeight,
                               inout uvec3 rays) {
  if (ls.pdf <= 0.0 || max3(ls.radiance) <= 0.0) return vec3(0.0);
  const vec3 f = bsdf_eval(bsdf, ls.direction);
  if (max3(f) <= 0.0) return vec3(0.0);
  if (!light_sample_visible(surface, ls, occlusionWeight, rays)) return vec3(0.0);
  const float weight = (ls.isDelta || HIPR_LIGHT_SAMPLING == kLightSamplingLightOnly)
                           ? 1.0
                           : power_heuristic(ls.pdf, scatter_pdf(bsdf, site, ls.direction));
  return f * ls.radiance * (weight / ls.pdf);
}

// Next-event estimation at a vertex: the light selection picks one light (u.x; a point on it:
// u.yz) for `direct`, in `group`'s share, and each punctual light sampled each adds its own
// (add_punctual_lights).
vec3 direct_light(SurfaceHit surface, BsdfPoint bsdf, GuideSite site, vec4 u, float occlusionWeight, inout uvec3 rays,
                  out uint group) {
  const LightSample ls = sample_light(surface.position, surface.shadingNormal, u);
  group = ls.group;
  return light_sample_contribution(surface, bsdf, site, ls, occlusionWeight, rays);
}

// One path in flight. A path advances one bounce per path_step call, so an invocation whose
// path ended can start its next sample while its SIMD neighbours are still bouncing.
struct PathState {
  PathRng rng;
  vec3 origin;
  vec3 direction;
  vec3 radiance;
  vec3 throughput;
  float previousPdf;
  bool previousDelta;  // the camera ray, and delta events, found radiance without MIS
  vec3 previousPosition;  // the last vertex and its shading normal (where MIS's light pick was made)
  vec3 previousNormal;
  uint depth;
  uint firstLobe;             // lobe sampled at x_0 (discovery path classes)
  bool specularSinceFirst;    // every lobe after x_0 so far was specular or transmission
  uint channel;               // the colour channel it carries since a dispersive surface, or kNoChannel
  bool guided;                // one of its vertices has been guided (no later one is)
};

// Adds a contribution to the path's radiance and to its light group's share. The share is what
// the radiance sum grew by, not `value` itself: radiance then comes from the same operations with
// or without groups (a second use of `value` could stop a compiler fusing its multiply into the
// add), so images are the same bit for bit.
void add_radiance(inout PathState p, uint group, vec3 value) {
#if HIPR_LIGHT_GROUPS > 0
  const vec3 before = p.radiance;
  p.radiance += value;
  if (group < HIPR_LIGHT_GROUPS) g_sampleGroups[group] += p.radiance - before;
#else
  p.radiance += value;
#endif
}

#if HIPR_GUIDE_TRAINING
// The training path's vertices (up to kTrainVertices): where it left each, in which bin, with
// what BSDF weight (f |cos| / pdf), the radiance it had gathered by then and its throughput
// onward. What it gathers later, divided by that throughput, is the radiance that arrived from
// that direction; times the weight, what the vertex reflected of it.
const uint kTrainVertices = 8u;
uint g_trainCount;
uint g_trainCell[kTrainVertices];
uint g_trainBin[kTrainVertices];
vec3 g_trainWeight[kTrainVertices];
vec3 g_trainRadiance[kTrainVertices];
vec3 g_trainThroughput[kTrainVertices];
#endif

PathState start_path(uvec2 pixel, uint sampleIndex, uint seed) {
  PathState p;
  p.rng = PathRng(pixel.y * u_frame.width + pixel.x, pixel, sampleIndex, seed, u_frame.sampleSequence);
  const vec4 u = rng_uniform4(p.rng, 0u, 2u);  // xy: where in the pixel, zw: where on the lens
  p.origin = u_frame.cameraPosition;
  p.direction = camera_ray_direction(pixel, u.xy);
  if (u_frame.lensRadius > 0.0) {
    // Thin lens: the ray through the pinhole meets the focus plane at `focus`; a ray from any
    // point of the lens disc to it sees that plane sharp and the rest blurred.
    const vec3 focus = p.origin + p.direction * (u_frame.focusDistance / dot(p.direction, u_frame.cameraForward));
    const vec2 disc = u_frame.lensRadius * sample_concentric_disk(u.zw);
    p.origin += disc.x * u_frame.cameraRight + disc.y * u_frame.cameraUp;
    p.direction = normalize(focus - p.origin);
  }
  p.radiance = vec3(0.0);
  p.throughput = vec3(1.0);
  p.previousPdf = 0.0;
  p.previousDelta = true;
  p.previousPosition = p.origin;
  p.previousNormal = p.direction;
  p.depth = 0u;
  p.firstLobe = kLobeDiffuse;
  p.specularSinceFirst = true;
  p.channel = kNoChannel;
  p.guided = false;
#if HIPR_LIGHT_GROUPS > 0
  for (uint g = 0u; g < HIPR_LIGHT_GROUPS; ++g) g_sampleGroups[g] = vec3(0.0);
#endif
#if HIPR_GUIDE_TRAINING
  g_trainCount = 0u;
#endif
  return p;
}

// Traces one segment and scatters; returns true when the path has ended. `backgroundTile`:
// the camera ray cannot hit anything (see main), so it misses without a query.
bool path_step(inout PathState p, bool backgroundTile, inout uvec3 rays) {
#if !HIPR_HAS_LIGHTS && !HIPR_DISCOVERY
  // Nothing emits and nothing can be sampled: every sample is black, whatever its path.
  // (Stage 2 still walks paths: discovery weighs throughput, not radiance.)
  return true;
#endif
#if HIPR_FEATURE_EMISSION == 0 && HIPR_FEATURE_ENVIRONMENT == 0
  // With nothing to find at the end of a segment but a surface, a segment toward the vertex
  // where the depth limit stops the path cannot add anything: not traced.
  if (p.depth >= u_frame.maxDepth) return true;
#endif
  RayHit hit;
  const bool query = p.depth > 0u || !backgroundTile;
  if (query) {
    if (p.depth == 0u) rays.x += 1u;
    else rays.y += 1u;
  }
  if (!query || !trace_closest(p.origin, p.direction, kFloatMax, hit)) {
    if (HIPR_FEATURE_ENVIRONMENT != 0 && u_frame.environmentLight != kInvalidIndex) {
      float weight = 1.0;
      if (!p.previousDelta)
        weight = bsdf_hit_weight(p.previousPdf,
                                 light_selection_pdf(u_frame.environmentLight, p.previousPosition, p.previousNormal) *
                                     env_pdf(p.direction));
      add_radiance(p, b_lights[u_frame.environmentLight].group, p.throughput * env_radiance(p.direction) * weight);
    }
    return true;
  }
  const SurfaceHit surface = make_surface_hit(hit.record, hit.primitive, hit.barycentrics, hit.objectToWorld,
                                              hit.worldToObject, p.direction);
  const vec3 wo = -p.direction;
  // The first dispersive dielectric on the path picks the colour channel it carries on.
  if (p.channel == kNoChannel && material_disperses(surface.material)) {
    p.channel = dispersion_channel(rng_uniform4(p.rng, p.depth, 3u).x);
    p.throughput *= dispersion_channel_weight(p.channel);
  }
  const ShadingParams shading = shading_params(surface, wo, p.channel);
  const OpenPbrParams params = shading.bsdf;
  // A ray that hits a transmissive solid from inside crossed its medium: Beer-Lambert.
  // (Media are not nested: a segment inside one solid that ends on another is not absorbed.)
  if (!surface.frontFacing && max3(shading.absorption) > 0.0) p.throughput *= exp(-shading.absorption * hit.t);
  if (HIPR_FEATURE_EMISSION != 0 && max3(shading.emission) > 0.0) {
    const float weight = p.previousDelta ? 1.0
                                         : emitter_hit_weight(surface, hit.t, p.direction, p.previousPdf,
                                                              p.previousPosition, p.previousNormal);
    add_radiance(p, b_material_groups[b_geometries[surface.geometry].materialIndex],
                 p.throughput * shading.emission * weight);
  }
  if (p.depth >= u_frame.maxDepth) return true;

  const BsdfPoint bsdf = bsdf_point(params, BsdfFrame(surface.shadingNormal, surface.geometricNormal, shading.tangent), wo);
  // One guided vertex per path: the mixed density weighs a direction up to 1 / (1 - share)
  // times BSDF sampling's weight, so each guided vertex may double the second moment of what
  // the path carries; in a closed room of pale walls, guided at every vertex, that compounded
  // into pixels hundreds of times their value (BENCHMARKS.md, "Path guiding").
  const GuideSite site = p.guided ? GuideSite(kInvalidIndex, 0.0) : guide_site(surface.position, bsdf);
  if (site.probability > 0.0) p.guided = true;
  if (HIPR_HAS_LIGHTS && u_frame.lightCount > 0u && HIPR_LIGHT_SAMPLING != kLightSamplingBsdfOnly) {
    // sample_light takes the choice of light in x and the point in y,z (rng_uniform4's layout).
    uint group;
    const vec3 direct =
        direct_light(surface, bsdf, site, rng_uniform4(p.rng, p.depth, 1u).zxyw, luminance(p.throughput), rays, group);
    add_radiance(p, group, p.throughput * direct);
#if HIPR_FEATURE_PUNCTUAL_LIGHTS
    // A scene's few punctual lights, each at every vertex: none is picked, so none brings the
    // noise of a pick (LightsPunctualLamp, five lamps: 0.23x the RMSE at 64 spp for 1.8x the time).
    // Their unshadowed light first; one that brings less than a tenth of the lights' sum traces
    // its shadow ray with a probability in proportion, its light divided by it (Russian
    // roulette: unbiased; uniforms of blocks 5 and 6, one a light). LightsPunctualLamp: a third
    // fewer shadow rays, the same error.
    vec3 unshadowed[kEachPunctualLights];
    float total = 0.0;
    for (uint i = 0u; i < u_frame.eachLightCount; ++i) {
      const LightSample ls = punctual_light_sample(b_lights[u_frame.eachLightOffset + i], surface.position, 1.0);
      unshadowed[i] = max3(ls.radiance) <= 0.0 ? vec3(0.0) : max(bsdf_eval(bsdf, ls.direction) * ls.radiance, vec3(0.0));
      total += luminance(unshadowed[i]);
    }
    const vec4 ua = total > 0.0 ? rng_uniform4(p.rng, p.depth, 5u) : vec4(1.0);
    const vec4 ub = total > 0.0 && u_frame.eachLightCount > 4u ? rng_uniform4(p.rng, p.depth, 6u) : vec4(1.0);
    for (uint i = 0u; i < u_frame.eachLightCount; ++i) {
      if (max3(unshadowed[i]) <= 0.0) continue;
      const float keep = min(1.0, luminance(unshadowed[i]) / (0.1 * total));
      const float u = i < 4u ? ua[i] : ub[i - 4u];
      if (!(u < keep)) continue;
      const Light light = b_lights[u_frame.eachLightOffset + i];
      const LightSample ls = punctual_light_sample(light, surface.position, 1.0);
      if (light_sample_visible(surface, ls, luminance(p.throughput), rays))
        add_radiance(p, light.group, p.throughput * (unshadowed[i] / keep));
    }
#endif
  }

  const vec4 u = rng_uniform4(p.rng, p.depth, 0u);
#if HIPR_GUIDING
  const BsdfSample bs =
      scatter_sample(bsdf, site, u.xyz, site.probability > 0.0 ? rng_uniform4(p.rng, p.depth, 4u).xyz : vec3(1.0));
#else
  const BsdfSample bs = bsdf_sample(bsdf, u.xyz);
#endif
#if HIPR_DISCOVERY
  if (p.depth >= 1u) {
    const uint pathClass = p.depth == 1u ? kPathDirect
                           : (p.firstLobe == kLobeDiffuse && p.specularSinceFirst) ? kPathCaustic : kPathIndirect;
    discover_vertex(surface.position, luminance(p.throughput) * discovery_lobe_weight(bs.lobe) * u_frame.wPath[pathClass] /
                                          float(1u + p.depth));
    p.specularSinceFirst = p.specularSinceFirst && (bs.lobe == kLobeSpecular || bs.lobe == kLobeTransmission);
  } else {
    p.firstLobe = bs.lobe;
  }
#endif
  if (bs.pdf <= 0.0) return true;
  p.throughput *= bs.weight;
  p.previousPdf = bs.pdf;
  p.previousDelta = bs.isDelta;
  p.previousPosition = surface.position;
  p.previousNormal = surface.shadingNormal;

  // Russian roulette from the second vertex on; unbiased because survivors are reweighted.
  // Starting it this early measured ~18% less error per second than after three bounces on
  // the Cornell box (fewer rays per sample outweigh the extra variance). Survival sqrt(beta)
  // (as Cycles), never capped below 1: with the Sobol sampler it measured 0.85x the RMSE at
  // 256 spp for 1.11x the time (1.25x the efficiency) against min(beta, 0.95), and a bright
  // path is never cut short.
  if (p.depth >= 1u) {
    const float survive = min(sqrt(max3(p.throughput)), 1.0);
    if (u.w >= survive) return true;
    p.throughput /= survive;
  }
  if (max3(p.throughput) <= 0.0) return true;
#if HIPR_GUIDE_TRAINING
  if (!bs.isDelta && g_trainCount < kTrainVertices) {
    g_trainCell[g_trainCount] = guide_cell(surface.position);
    g_trainBin[g_trainCount] = guide_bin(bs.direction);
    g_trainWeight[g_trainCount] = bs.weight;
    g_trainRadiance[g_trainCount] = p.radiance;
    g_trainThroughput[g_trainCount] = p.throughput;
    g_trainCount += 1u;
  }
#endif
  p.origin = leave_surface(surface.position, surface.geometricNormal, bs.direction);
  p.direction = bs.direction;
  p.depth += 1u;
  return false;
}

#if HIPR_GUIDE_TRAINING
// Training (GuidePass): each pixel of the frame traces `samplesPerPixel` paths with the seed
// salted (the render's own samples stay independent of what the guide learnt) and splats what
// each vertex received into its cell. Nothing is accumulated. Every splat is an integer atomic
// add, so the guide is the same whatever order the paths run in.
void main() {
  const uint pixelIndex = gl_GlobalInvocationID.x;
  if (pixelIndex >= u_frame.width * u_frame.height) return;
  const uvec2 pixel = uvec2(pixelIndex % u_frame.width, pixelIndex / u_frame.width);
  const uint seed = u_frame.seed ^ 0x6a09e667u;
  uvec3 rays = uvec3(0u);
  for (uint s = 0u; s < u_push.samplesPerPixel; ++s) {
    PathState path = start_path(pixel, s, seed);
    while (!path_step(path, false, rays)) {}
    for (uint k = 0u; k < g_trainCount; ++k) {
      const vec3 t = g_trainThroughput[k];
      const vec3 gathered = path.radiance - g_trainRadiance[k];
      const vec3 arrived = vec3(t.x > 0.0 ? gathered.x / t.x : 0.0, t.y > 0.0 ? gathered.y / t.y : 0.0,
                                t.z > 0.0 ? gathered.z / t.z : 0.0);
      guide_splat(g_trainCell[k], g_trainBin[k], luminance(max(arrived * g_trainWeight[k], vec3(0.0))));
    }
  }
  atomicAdd(b_stats.guideRays, uint64_t(rays.x + rays.y + rays.z));
}
#else
void main() {
  uvec2 pixel;
  if (!tile_pixel(u_push.listOffset, u_push.tileCount, u_push.tileStride, u_push.groupsPerTile, u_push.requireFlags,
                  u_push.skipFlags, pixel))
    return;
  const uint pixelIndex = pixel.y * u_frame.width + pixel.x;
  // No camera ray of this tile can reach any instance's bounds (src/render/background_tiles.cpp):
  // its samples are what a miss gives, with the same random numbers, without a ray query.
  const uint tile = tile_of_pixel(pixel);
  const bool backgroundTile = b_tile_background[tile] != 0u;
  PixelAccum accum = b_accum[pixelIndex];
  const bool restart = (accum.count & kPixelOwed) != 0u;  // first visit since an edit
  // With a round target the visit adds what the pixel lacks of it: a round the scheduler
  // re-planned midway (a new focus) still leaves every pixel with the same count, and the
  // focus's tiles run ahead to their own target (docs/method.md#focus).
  const bool focusTile = u_push.focusTarget != 0u && (b_tile_flags[tile] & kTileFocus) != 0u;
  uint target = focusTile ? u_push.focusTarget : u_push.sampleTarget;
  // A pixel stage 1 saw change most (a moved object, a surface it no longer sees) runs ahead to
  // the edit's lead (docs/method.md#the-edits-lead).
  // (The bit is read only while a lead is on: most dispatches have none.)
  if (target != 0u && u_push.leadTarget != 0u && (b_pixel_lead[pixelIndex / 32u] & (1u << (pixelIndex % 32u))) != 0u)
    target = max(target, u_push.leadTarget);
  const uint have = restart ? 0u : accum.count;
  const uint samples = target == 0u ? u_push.samplesPerPixel : (have >= target ? 0u : target - have);
  if (samples == 0u) return;
  if (restart) accum = PixelAccum(vec3(0.0), 0u, vec3(0.0));
#if HIPR_LIGHT_GROUPS > 0
  vec3 groupSums[HIPR_LIGHT_GROUPS];
  for (uint g = 0u; g < HIPR_LIGHT_GROUPS; ++g)
    groupSums[g] = restart ? vec3(0.0) : b_group_sums[pixelIndex * HIPR_LIGHT_GROUPS + g];
#endif
#if HIPR_DIFFERENCE
  // Records change only at a restart (the sums start over) and for the first samples.
  const bool noteSamples = restart || accum.count < kDifferenceSamples;
  DifferenceRecord record;
  vec3 stale = vec3(0.0);
  uint valid = 0u;
  if (noteSamples) {
    record = b_difference[pixelIndex];
    const DisplayTexel texel = b_display[pixelIndex];
    stale = texel.stale;
    valid = texel_valid(texel.flags);
    if (restart) clear_record_sums(record);
  }
#endif
  uvec3 rays = uvec3(0u);
  uint nonFinite = 0u;
  // Samples finish in index order, so the sum is the same whatever the dispatch size.
  uint finished = 0u;
  PathState path = start_path(pixel, accum.count, u_frame.seed);
  while (finished < samples) {
    if (!path_step(path, backgroundTile, rays)) continue;
    const vec3 value = path.radiance;
    const bool finite = !any(isnan(value)) && !any(isinf(value));
#if HIPR_DIFFERENCE
    // A dropped sample adds nothing to the sum: it counts as black here too.
    if (accum.count + finished < kDifferenceSamples)
      note_sample(record, accum.count + finished, finite ? value : vec3(0.0), valid, stale);
#endif
    if (!finite) nonFinite += 1u;  // dropped, and counted
    else {
      accum.sum += value;
      accum.sumSquares += value * value;
#if HIPR_LIGHT_GROUPS > 0
      for (uint g = 0u; g < HIPR_LIGHT_GROUPS; ++g) groupSums[g] += g_sampleGroups[g];
#endif
    }
    finished += 1u;
    if (finished < samples) path = start_path(pixel, accum.count + finished, u_frame.seed);
  }
  accum.count += samples;
  b_accum[pixelIndex] = accum;
#if HIPR_DIFFERENCE
  if (noteSamples) b_difference[pixelIndex] = record;
#endif
#if HIPR_LIGHT_GROUPS > 0
  for (uint g = 0u; g < HIPR_LIGHT_GROUPS; ++g) b_group_sums[pixelIndex * HIPR_LIGHT_GROUPS + g] = groupSums[g];
#endif

  atomicAdd(b_stats.rays, uint64_t(rays.x + rays.y + rays.z));
  atomicAdd(b_stats.cameraRays, uint64_t(rays.x));
  atomicAdd(b_stats.shadowRays, uint64_t(rays.z));
  atomicAdd(b_stats.samples, uint64_t(samples));
  if (nonFinite > 0u) atomicAdd(b_stats.nonFiniteSamples, nonFinite);
}
#endif
