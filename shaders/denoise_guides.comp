#version 460
// The display denoiser's guides: one ray through every pixel centre (the ray of visibility.comp)
// records the surface it hits, how far, its normal facing the camera, the albedo the
// radiance is demodulated by and the radiance the surface emits toward the camera; a pixel whose
// centre sees the environment, the surface its footprint finds (an outline) or else the
// environment's mean over its footprint. Run when the scene or the camera changed.
// Reads: TLAS (or the software BVH), FrameParams, geometry, materials and textures.
// Writes: DenoiseGuide per pixel, and its normal and distance packed (what the a-trous passes
// read of a neighbour).
#extension GL_GOOGLE_include_directive : require
// The guide ray stands for the pixel's samples: a stochastic (BLEND) surface stops it where it
// stops most of them (common/cutout.glsl), or where nothing else would (main). A 5 %-opaque
// sphere otherwise stopped one guide ray in twenty: those pixels were keyed to it, apart from
// the wall all of them show.
#define HIPR_CUTOUT_MAJORITY 1
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/scene_bindings.glsl"
#include "common/denoise.glsl"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"
#include "common/sampling.glsl"
#include "common/textures.glsl"
#include "bsdf/bsdf.glsl"
#include "common/surface.glsl"
#include "common/material_inputs.glsl"
#include "common/cutout.glsl"
#include "common/scene_trace.glsl"
#include "common/environment.glsl"

layout(scalar, binding = kDenoiseGuides) writeonly buffer Guides { DenoiseGuide b_guides[]; };
// What the a-trous passes read of a neighbour's guide, packed: 8 bytes a tap, not 24.
layout(scalar, binding = kDenoiseGeometry) writeonly buffer Geometry { uvec2 b_geometry[]; };

// A pixel whose centre sees the environment: when no ray of a kFootprintRays x kFootprintRays
// grid over the pixel hits a surface either, its samples are all environment lookups (the
// camera rays of trace_tiles.comp, jittered over the pixel), and their mean over the footprint
// is known here better than a few samples tell it: the mean of kFootprintLookups stratified
// lookups. The denoised display shows that while the pixel has fewer samples
// (denoise_prepare.comp: kept_value, which also catches what lies between these rays): a
// high-frequency environment seen directly (a curtain, foliage) otherwise shows its few samples'
// aliasing and flickers as they arrive. The same grid finds the surface of an outline pixel
// (main). Cost: 16 rays and 128 lookups per such pixel when the scene or the camera changed
// (SheenChair at 512 x 512 on lavapipe: guides and a filter 0.53 s against 0.28 s without,
// most of it the lookups' trigonometry; the first denoise 0.72 s against 0.60 s with a 2 x 2
// grid). With a 2 x 2 grid, 11 more of SheenChair's outline pixels (128 x 128, 4 spp) missed the
// chair and showed the environment alone, below 0.3x the reference.
const uint kFootprintRays = 4u;

vec2 grid_point(uint i, uint n) { return (vec2(i % n, i / n) + 0.5) / float(n); }

// The i-th of n Hammersley points (n a power of two): a (0, m, 2)-net, stratified in every
// elementary interval of area 1/n, so an edge of the environment's texels or a thin bright line
// through the pixel is resolved to 1/n of it, not to 1/sqrt(n) as a grid resolves one along an
// axis.
vec2 hammersley(uint i, uint n) { return vec2((float(i) + 0.5) / float(n), float(bitfieldReverse(i)) * 2.3283064365386963e-10); }

// The first surface any of the pixel's rays may stop at along `direction`: a stochastic one
// whatever its opacity (trace_closest stops where most of them stop).
bool trace_first_possible(vec3 direction, out RayHit hit) {
  g_cutoutStopsFrom = 0.0;
  const bool found = trace_closest(u_frame.cameraPosition, direction, 3.0e38, hit);
  g_cutoutStopsFrom = 0.5;
  return found;
}

// The first surface a grid of rays over a pixel whose centre sees the environment finds, in
// `hit` and the ray's `direction`; false where they all see the environment. (A veil in front of
// the environment counts: some samples see it.)
bool footprint_finds_surface(uvec2 pixel, out RayHit hit, out vec3 direction) {
  for (uint i = 0u; i < kFootprintRays * kFootprintRays; ++i) {
    direction = camera_ray_direction(pixel, grid_point(i, kFootprintRays));
    if (trace_first_possible(direction, hit)) return true;
  }
  return false;
}

// The environment's mean over the pixel, and the standard deviation of its luminance there.
vec3 footprint_environment(uvec2 pixel, out float deviation) {
  const uint n = kFootprintLookups;
  vec3 sum = vec3(0.0);
  float squares = 0.0;
  for (uint i = 0u; i < n; ++i) {
    const vec3 radiance = env_radiance(camera_ray_direction(pixel, hammersley(i, n)));
    sum += radiance;
    squares += denoise_luminance(radiance) * denoise_luminance(radiance);
  }
  const vec3 mean = sum / float(n);
  deviation = sqrt(max(squares / float(n) - denoise_luminance(mean) * denoise_luminance(mean), 0.0));
  return mean;
}

// The share of light a surface reflects or passes on, as a colour: the base colour for
// diffuse and metal alike (glTF's metal tints its reflection by it), white where light goes
// through (glass shows what lies behind it, not its own colour).
vec3 surface_albedo(SurfaceHit hit) {
  const uint material = hit.material;
  const vec3 base = material_color(b_materials[material].base_color, b_materials[material].base_color_texture, hit) *
                    b_materials[material].base_weight;
  const float transmission = HIPR_FEATURE_TRANSMISSION != 0 ? clamp(material_transmission_weight(hit), 0.0, 1.0) : 0.0;
  return clamp(mix(base, vec3(1.0), transmission), 0.0, 1.0);
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_frame.width * u_frame.height) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const vec3 direction = pixel_centre_ray(pixel);
  DenoiseGuide guide = DenoiseGuide(kInvalidIndex, 0.0, 0u, packUnorm4x8(vec4(1.0)), 0u, 0u);
  RayHit hit;
  // Veiled: the pixel's rays stop at more than one surface (a stochastic one in front), so the
  // record its shown value was rendered with may be another than the guide's (denoise_keys.comp).
  bool veiled = false;
#if HIPR_FEATURE_CUTOUT
  // The first surface any of the pixel's rays may stop at and the first most of them stop at:
  // one trace where the first is also the second (every surface most rays stop at is one some
  // may stop at, so none of those lies nearer), a second trace only behind a veil.
  bool found = trace_first_possible(direction, hit);
  if (found && !cutout_hit(hit.record, hit.primitive, hit.barycentrics, u_frame.cameraPosition, direction)) {
    RayHit behind;
    const bool stops_behind = trace_closest(u_frame.cameraPosition, direction, 3.0e38, behind);
    veiled = !stops_behind || behind.record != hit.record;
    // Nothing that most of the pixel's rays stop at: the guide stays the veil some of them stop
    // at before the environment, still where its noise comes from (a vase of 30 % opaque glass,
    // the studio behind it), and its pixels are filtered together.
    if (stops_behind) hit = behind;
  }
#else
  bool found = trace_closest(u_frame.cameraPosition, direction, 3.0e38, hit);
#endif
  // A pixel on a silhouette whose centre sees the environment: its samples mix the surface
  // beside it and the environment, and at a few samples all of them may happen to fall on one
  // side (SheenChair at 4 spp: the chair's outline dark or lit in dots). Shown as it was (the
  // environment's key mixes with nothing), it kept that coverage noise; it takes the surface
  // its footprint finds instead, veiled (denoise_keys.comp: beside an edge of that surface, its
  // value of two surfaces), and is filtered with the surface's other silhouette pixels. Its
  // emission is not set apart: the surface covers only part of it.
  vec3 surfaceDirection = direction;
  bool besideSurface = false;
  if (!found && footprint_finds_surface(pixel, hit, surfaceDirection)) {
    found = true;
    veiled = true;
    besideSurface = true;
  }
  if (!found) {
    if (HIPR_FEATURE_ENVIRONMENT != 0 && u_frame.environmentLight != kInvalidIndex) {
      float deviation;
      const vec3 environment = footprint_environment(pixel, deviation);
      guide.emissionRG = packHalf2x16(environment.rg);
      guide.emissionB = packHalf2x16(vec2(environment.b, max(deviation, kFootprintDeviationFloor)));
    }
  } else {
    const SurfaceHit surface =
        make_surface_hit(hit.record, hit.primitive, hit.barycentrics, hit.objectToWorld, hit.worldToObject, surfaceDirection);
    guide.record = hit.record;
    guide.distance = hit.t;
    // The normal before any normal map: one ray samples the map's detail at a point of the
    // pixel (aliased where the detail is finer), and the a-trous passes' normal and plane
    // weights then kept a normal-mapped surface's pixels nearly apart (SheenChair at 4 spp:
    // FLIP 0.0338 with the mapped normal, 0.0324 without). The detail's shading is in the
    // radiance.
    guide.normal = pack_normal(surface.vertexNormal);
    guide.albedo = packUnorm4x8(vec4(surface_albedo(surface), besideSurface ? kGuideOutline : veiled ? 0.0 : 1.0));
    // As the camera path adds it at its first hit (trace_tiles.comp: shading_params).
    const bool emits =
        !besideSurface && (surface.frontFacing || (b_materials[surface.material].flags & kMaterialDoubleSided) != 0u);
    const vec3 emission =
        emits ? material_emission(surface.material, surface.uvs, dot(surface.geometricNormal, -direction)) : vec3(0.0);
    guide.emissionRG = packHalf2x16(emission.rg);
    guide.emissionB = packHalf2x16(vec2(emission.b, 0.0));
  }
  b_guides[index] = guide;
  b_geometry[index] = uvec2(guide.normal, floatBitsToUint(guide.distance));
}
