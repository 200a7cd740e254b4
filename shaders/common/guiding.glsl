// Path guiding (docs/method.md#path-guiding): where light comes from, learnt per cell of a grid
// over the scene by a training pass, sampled in one-sample MIS against the BSDF.
// A cell's direction bins split the sphere into kGuidePhiBins azimuths about +Y x kGuideCosBins
// bands of cos(theta) to +Y: bins of equal solid angle (4 pi / kGuideBins), so a bin's density is
// its probability over that solid angle.
// Needs scene_bindings.glsl. HIPR_GUIDE_TRAINING 1 (the training kernel) also writes the counts.
#ifndef HIPR_GUIDING_GLSL
#define HIPR_GUIDING_GLSL

#ifndef HIPR_GUIDING
#define HIPR_GUIDING 0
#endif
#ifndef HIPR_GUIDE_TRAINING
#define HIPR_GUIDE_TRAINING 0
#endif

layout(scalar, set = kSceneSet, binding = kSceneGuide) readonly buffer Guide { float b_guide[]; };
#if HIPR_GUIDE_TRAINING
layout(scalar, set = kSceneSet, binding = kSceneGuideCounts) buffer GuideCounts { uint64_t b_guide_counts[]; };
#endif

const float kGuideBinSolidAngle = 4.0 * 3.14159265358979 / float(kGuideBins);

// The cell holding `position`, or kInvalidIndex where there is no guide.
uint guide_cell(vec3 position) {
  if (u_frame.guideCells == 0u) return kInvalidIndex;
  const uvec3 resolution = uvec3(u_frame.guideResolutionX, u_frame.guideResolutionY, u_frame.guideResolutionZ);
  const vec3 c = (position - u_frame.guideLo) * u_frame.guideInvCell;
  // Points on the bounds' faces (and rounding past them) belong to the outer cells.
  const uvec3 i = uvec3(clamp(ivec3(floor(c)), ivec3(0), ivec3(resolution) - 1));
  return (i.z * resolution.y + i.y) * resolution.x + i.x;
}

uint guide_bin(vec3 direction) {
  const float phi = atan(direction.z, direction.x);  // [-pi, pi]
  const uint p = min(uint((phi + 3.14159265358979) * (float(kGuidePhiBins) / 6.28318530717959)), kGuidePhiBins - 1u);
  const uint c = min(uint((clamp(direction.y, -1.0, 1.0) + 1.0) * (0.5 * float(kGuideCosBins))), kGuideCosBins - 1u);
  return c * kGuidePhiBins + p;
}

// Where a path's direction is chosen: the cell and how often the guide chooses it there.
struct GuideSite {
  uint cell;
  float probability;  // 0: BSDF sampling alone
};

// The guide samples only the part of a BSDF that spreads light evenly (diffuse, fuzz): a glossy
// lobe finds its few directions better than any bin, and where the BSDF's sampling follows a
// glossy lobe less closely than its value (a lobe picked with a small probability), directions
// the guide sends into it would weigh too much.
GuideSite guide_site(vec3 position, BsdfPoint bsdf) {
  GuideSite site = GuideSite(kInvalidIndex, 0.0);
#if HIPR_GUIDING
  site.cell = guide_cell(position);
  if (site.cell == kInvalidIndex) return site;
  const float spread = bsdf.context.diffuseWeight + bsdf.context.fuzzWeight;
  site.probability = b_guide[site.cell * kGuideSlots + kGuideBins] * clamp(spread, 0.0, 1.0);
#endif
  return site;
}

// The guide's density of `direction` (solid angle).
float guide_pdf(GuideSite site, vec3 direction) {
  if (site.probability <= 0.0) return 0.0;
  const uint base = site.cell * kGuideSlots;
  const uint bin = guide_bin(direction);
  const float below = bin == 0u ? 0.0 : b_guide[base + bin - 1u];
  return max(b_guide[base + bin] - below, 0.0) / kGuideBinSolidAngle;
}

// A direction drawn from the guide: a bin by its CDF (u.x, reused within the bin), then a
// uniform point of the bin (u.y).
vec3 guide_sample(GuideSite site, vec2 u, out float pdf) {
  const uint base = site.cell * kGuideSlots;
  uint lo = 0u, hi = kGuideBins - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi) / 2u;
    if (b_guide[base + mid] > u.x) hi = mid;
    else lo = mid + 1u;
  }
  const float below = lo == 0u ? 0.0 : b_guide[base + lo - 1u];
  const float width = b_guide[base + lo] - below;
  pdf = max(width, 0.0) / kGuideBinSolidAngle;
  const float inBin = width > 0.0 ? clamp((u.x - below) / width, 0.0, 0.99999994) : 0.5;
  const float phi = (float(lo % kGuidePhiBins) + inBin) * (6.28318530717959 / float(kGuidePhiBins)) - 3.14159265358979;
  const float cosTheta = clamp((float(lo / kGuidePhiBins) + u.y) * (2.0 / float(kGuideCosBins)) - 1.0, -1.0, 1.0);
  const float sinTheta = sqrt(max(1.0 - cosTheta * cosTheta, 0.0));
  return vec3(sinTheta * cos(phi), cosTheta, sinTheta * sin(phi));
}

#if HIPR_GUIDE_TRAINING
// Fixed point of the training sums: integer atomics add up in any order to the same total, so
// the guide does not depend on how the GPU schedules the training paths.
const float kGuideFixedPoint = 1048576.0;  // 2^20
const float kGuideSplatLimit = 1048576.0;  // a splat's value is capped at 2^20 (2^40 fixed point)

// One sample of the light a vertex in `cell` reflected from the bin of its sampled direction:
// the radiance that arrived times f |cos| / pdf estimates the bin's share of the reflected light,
// so the guide learns the product of the incident light and the cell's BSDFs and cosines.
void guide_splat(uint cell, uint bin, float value) {
  if (cell == kInvalidIndex) return;
  // NaN fails the test below; infinity is capped.
  const uint base = cell * kGuideSumSlots;
  if (value > 0.0) {
    const uint64_t fixedPoint = uint64_t(min(value, kGuideSplatLimit) * kGuideFixedPoint);
    atomicAdd(b_guide_counts[base + bin], fixedPoint);
    atomicMax(b_guide_counts[base + kGuideBins + bin], fixedPoint);
  }
  atomicAdd(b_guide_counts[base + 2u * kGuideBins], uint64_t(1));
}
#endif

#endif
