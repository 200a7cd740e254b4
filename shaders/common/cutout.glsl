// Opacity cutout (glTF alphaMode MASK / BLEND, OpenPBR geometry_opacity): the test a ray runs
// on a candidate triangle of geometry whose material is not opaque (scene_trace.glsl, for both
// traversals); opaque geometry never runs it. A kernel without HIPR_FEATURE_CUTOUT (every
// material opaque) has no candidate code at all.
// Needs scene_bindings.glsl (scene buffers) and textures.glsl.
#ifndef HIPR_CUTOUT_GLSL
#define HIPR_CUTOUT_GLSL

#include "features.glsl"

// 1 where a kernel's rays stand for a pixel's many (cutout_hit): defined before this include.
#ifndef HIPR_CUTOUT_MAJORITY
#define HIPR_CUTOUT_MAJORITY 0
#endif
#if HIPR_CUTOUT_MAJORITY
// The opacity from which such a ray stops at a stochastic (BLEND) surface, set by the kernel
// per ray: 0.5, where most of the pixel's rays stop; 0, at any surface some of them may stop at.
float g_cutoutStopsFrom = 0.5;
#endif
#include "rng.glsl"
#include "vertices.glsl"

// A uniform number in [0,1) fixed by the ray and the triangle (its record's identity and its
// primitive): the same ray makes the same choice whatever tile order, dispatch size or edit
// history produced it, so renders stay deterministic.
float cutout_random(vec3 origin, vec3 direction, uint identity, uint primitive) {
  const uvec4 h = rng_hash4(uvec4(floatBitsToUint(origin), primitive));
  return float(rng_hash4(uvec4(floatBitsToUint(direction), identity) ^ h).x >> 8u) * (1.0 / 16777216.0);
}

// Opacity at a point of the triangle: geometry_opacity x base colour texture alpha (unless
// alphaMode OPAQUE). Returns the material's alpha_cutoff in `cutoff`.
float cutout_opacity(uint record, uint primitive, vec2 bary, out float cutoff) {
  const GeometryRecord g = b_geometries[record];
  float opacity = b_materials[g.materialIndex].geometry_opacity;
  const uint texture = hipr_texture_slot(b_materials[g.materialIndex].base_color_texture);
  if (texture != kInvalidIndex && (b_materials[g.materialIndex].flags & kMaterialIgnoreTextureAlpha) == 0u)
    opacity *= sample_texture(texture, interpolate_uv(triangle_vertices(g, primitive), bary)).a;
  cutoff = b_materials[g.materialIndex].alpha_cutoff;
  return opacity;
}

// Whether a ray stops at this point: the opacity thresholded at alpha_cutoff (MASK) or, with no
// cutoff, a stop with probability opacity (stochastic BLEND: the right coverage on average).
bool cutout_hit(uint record, uint primitive, vec2 bary, vec3 origin, vec3 direction) {
  float cutoff;
  const float opacity = cutout_opacity(record, primitive, bary, cutoff);
  if (cutoff >= 0.0) return opacity >= cutoff;
#if HIPR_CUTOUT_MAJORITY
  // A ray that stands for the whole pixel (the denoiser's guide) stops where most rays through
  // the point stop (the layer most of the pixel's samples see, not one a few of them see), or at
  // any surface they may stop at (g_cutoutStopsFrom).
  return opacity > 0.0 && opacity >= g_cutoutStopsFrom;
#else
  return cutout_random(origin, direction, b_geometries[record].identity, primitive) < opacity;
#endif
}

// The mean of cutout_hit over rays: what light sampling weights an emitter's radiance by, so
// it agrees with BSDF sampling, whose rays find the emitter only where cutout_hit lets them.
float cutout_coverage(uint record, uint primitive, vec2 bary) {
  if (HIPR_FEATURE_CUTOUT == 0) return 1.0;
  float cutoff;
  const float opacity = cutout_opacity(record, primitive, bary, cutoff);
  return cutoff >= 0.0 ? (opacity >= cutoff ? 1.0 : 0.0) : opacity;
}

#endif
