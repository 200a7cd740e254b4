// Light selection (the light tree for lights at finite distance, a CDF by estimated power for
// the rest; or one CDF over all, --light-selection power) and next-event sampling of emissive
// triangles, punctual lights and the environment; a scene's few punctual lights are not picked
// but each sampled (punctual_light_sample, FrameParams::eachLightCount). Needs cutout.glsl: a
// cut-out emitter emits only where it is there.
#ifndef HIPR_LIGHTS_GLSL
#define HIPR_LIGHTS_GLSL

#include "features.glsl"
#include "light_tree.glsl"

struct LightSample {
  vec3 direction;   // from the shading point toward the light, unit
  float distance;   // to the sampled point; kFloatMax for lights at infinity
  vec3 radiance;    // arriving radiance (or intensity / d^2 for delta lights)
  float pdf;        // solid-angle pdf including the selection probability; 0 = no sample
  bool isDelta;     // point/spot/directional: no MIS
  vec3 lightNormal; // triangle: the sampled point's normal facing the shading point
  uint group;       // the light's group (Light::group)
};

// The probability of picking light `index` at a point (position, shading normal).
float light_selection_pdf(uint index, vec3 position, vec3 normal) {
  const uint leaf = b_lights[index].treeLeaf;
  if (u_frame.lightTreeProbability > 0.0 && leaf != kInvalidIndex)
    return u_frame.lightTreeProbability * light_tree_pmf(leaf, position, normal);
  const uint at = u_frame.lightCdfOffset + index;
  return (1.0 - u_frame.lightTreeProbability) * (b_light_cdf[at + 1u] - b_light_cdf[at]);
}

// Binary search of the CDF the frame names.
uint select_light_by_power(float u) {
  uint lo = 0u, hi = u_frame.lightCount - 1u;
  while (lo < hi) {
    const uint mid = (lo + hi) >> 1u;
    if (b_light_cdf[u_frame.lightCdfOffset + mid + 1u] > u) hi = mid;
    else lo = mid + 1u;
  }
  return lo;
}

// Picks a light for a point with u in [0, 1) and gives its probability (0: none).
uint select_light(float u, vec3 position, vec3 normal, out float selection) {
  const float pTree = u_frame.lightTreeProbability;
  if (u < pTree) {
    const uint index = light_tree_pick(position, normal, min(u / pTree, 0.99999994), selection);
    selection *= pTree;
    return index;
  }
  // (With no tree pTree is 0 and u stays as it is: the selection before the tree, bit for bit.)
  const uint index = select_light_by_power(pTree > 0.0 ? min((u - pTree) / (1.0 - pTree), 0.99999994) : u);
  selection = light_selection_pdf(index, position, normal);
  return index;
}

// glTF's recommended range falloff: smooth window to zero at `range`.
float range_window(float distance, float range) {
  if (range <= 0.0) return 1.0;
  const float r = distance / range;
  const float w = clamp(1.0 - r * r * r * r, 0.0, 1.0);
  return w * w;
}

// What a point or spot light sends to `position`: the unit direction toward the light, its
// distance and the intensity x range window x cone / d^2 that arrives (0 outside range or cone).
// False where the point is the light's own position.
bool point_light_arrival(Light light, vec3 position, out vec3 direction, out float distance, out vec3 arriving) {
  const vec3 toLight = light.position - position;
  const float d2 = dot(toLight, toLight);
  if (d2 <= 0.0) return false;
  distance = sqrt(d2);
  direction = toLight / distance;
  float falloff = range_window(distance, light.range) / d2;
  if (light.type == kLightSpot) {
    const float cd = dot(light.direction, -direction);
    const float t = clamp((cd - light.spotCosOuter) / max(light.spotCosInner - light.spotCosOuter, 1e-4), 0.0, 1.0);
    falloff *= t * t;
  }
  arriving = light.intensity * falloff;
  return true;
}

// Solid-angle pdf of reaching a point on triangle light `light` from `origin`.
float triangle_light_pdf(Light light, float distance, float cosAtLight) {
  if (cosAtLight <= 0.0 || light.area <= 0.0) return 0.0;
  return distance * distance / (light.area * cosAtLight);
}

LightSample no_light_sample() {
  LightSample s;
  s.pdf = 0.0;
  s.isDelta = false;
  s.distance = kFloatMax;
  s.radiance = vec3(0.0);
  s.lightNormal = vec3(0.0);
  s.group = kInvalidIndex;
  return s;
}

// What punctual light `light` (point, spot or directional) sends to `position`, as a sample of
// probability `selection`.
LightSample punctual_light_sample(Light light, vec3 position, float selection) {
  LightSample s = no_light_sample();
  s.group = light.group;
  if (light.type == kLightDirectional) {
    s.direction = -light.direction;
    s.radiance = light.intensity;
  } else {
    vec3 direction, arriving;
    float distance;
    if (!point_light_arrival(light, position, direction, distance, arriving)) return s;
    s.direction = direction;
    s.distance = distance;
    s.radiance = arriving;
  }
  s.pdf = selection;
  s.isDelta = true;
  return s;
}

// Whether light selection picks among any lights: not where the only lights are the punctual
// ones sampled each (kEachPunctualLights).
bool lights_to_pick() { return u_frame.lightCount > u_frame.eachLightCount; }

// One light picked for the point (never one of the punctual lights sampled each: a CDF with
// nothing of power left gives every entry an equal share) and a point on it.
LightSample sample_light(vec3 position, vec3 normal, vec4 u) {
  LightSample s = no_light_sample();
  if (!lights_to_pick()) return s;
  float selection;
  const uint index = select_light(u.x, position, normal, selection);
  if (!(selection > 0.0) || index - u_frame.eachLightOffset < u_frame.eachLightCount) return s;
  const Light light = b_lights[index];
  s.group = light.group;

  // Light kinds the kernel was compiled without are never in the table (features.glsl).
  if (HIPR_FEATURE_EMISSION != 0 && light.type == kLightTriangle) {
    const vec2 b = sample_triangle(u.yz);
    const vec3 p = light.position + b.x * light.edge1 + b.y * light.edge2;
    vec3 n = cross(light.edge1, light.edge2);
    if (dot(n, n) <= 0.0) return s;
    n = normalize(n);
    const vec3 toLight = p - position;
    const float d2 = dot(toLight, toLight);
    if (d2 <= 0.0) return s;
    s.distance = sqrt(d2);
    s.direction = toLight / s.distance;
    float cosAtLight = -dot(n, s.direction);
    const GeometryRecord g = b_geometries[light.geometryRecord];
    const bool doubleSided = (b_materials[g.materialIndex].flags & kMaterialDoubleSided) != 0u;
    if (cosAtLight <= 0.0 && !doubleSided) return s;
    s.lightNormal = cosAtLight < 0.0 ? -n : n;
    cosAtLight = abs(cosAtLight);
    const uvec3 v = triangle_vertices(g, light.primitive);
    s.radiance = material_emission(g.materialIndex, interpolate_uv(v, b), cosAtLight) *
                 cutout_coverage(light.geometryRecord, light.primitive, b);
    s.pdf = selection * triangle_light_pdf(light, s.distance, cosAtLight);
  } else if (HIPR_FEATURE_ENVIRONMENT != 0 && light.type == kLightEnvironment) {
    float pdf;
    s.direction = env_sample(u.yz, pdf);
    s.radiance = env_radiance(s.direction);
    s.pdf = selection * pdf;
  } else if (HIPR_FEATURE_PUNCTUAL_LIGHTS != 0) {
    return punctual_light_sample(light, position, selection);
  }
  return s;
}

#endif
