// Reading the view before a camera edit from the view after it (reproject_display.comp): where
// a new pixel's surface was on the old screen, and the estimates of a pixel's value from the
// old display where the plain bilinear reading does not hold (beside edges, disocclusions).
// Needs, declared before it: u_frame (frame.glsl), u_view (the old view), b_gbuffer and
// b_previous (the new and old G-buffers), b_before (the old display), b_geometries and
// b_materials (scene_bindings.glsl).
#ifndef HIPR_REPROJECTION_GLSL
#define HIPR_REPROJECTION_GLSL

const vec3 kLuma = vec3(0.2126, 0.7152, 0.0722);

// Where `offset` (a point minus the old camera's position, or a direction) lands in the old
// view: continuous pixel coordinates and the depth along its axis; false behind the camera.
bool project_before(vec3 offset, out vec2 pixel, out float depth) {
  pixel = vec2(0.0);
  depth = dot(offset, u_view.forward);
  if (!(depth > 0.0)) return false;
  const float sx = dot(offset, u_view.right) / (depth * u_view.tanHalfFovY * u_view.aspect);
  const float sy = dot(offset, u_view.up) / (depth * u_view.tanHalfFovY);
  pixel = vec2((sx + 1.0) * 0.5 * float(u_frame.width), (1.0 - sy) * 0.5 * float(u_frame.height));
  return !any(isnan(pixel)) && !any(isinf(pixel));
}

// Where the surface a new pixel sees through its centre was in the old view (continuous pixel
// coordinates) and its depth along the old axis; false behind the old camera. Background pixels
// by direction (the environment does not move with the camera). Far off screen (a point near
// the old camera's plane lands anywhere) is clamped to just off it, within what converts to an
// int.
bool where_before(uvec2 pixel, GBufferTexel now, out vec2 at, out float depth) {
  const vec3 ray = pixel_centre_ray(pixel);
  const vec3 offset = now.record == kInvalidIndex
                          ? ray
                          : u_frame.cameraPosition + ray * (now.depth / dot(ray, u_frame.cameraForward)) - u_view.position;
  const bool inFront = project_before(offset, at, depth);
  at = clamp(at, vec2(-4.0), vec2(u_frame.width + 4u, u_frame.height + 4u));
  return inFront;
}

bool on_screen(ivec2 p) { return p.x >= 0 && p.y >= 0 && p.x < int(u_frame.width) && p.y < int(u_frame.height); }

uint texel_index(ivec2 p) { return uint(p.y) * u_frame.width + uint(p.x); }

// The bilinear weight of corner k (0-3: x then y) of the four pixel centres around a point whose
// fraction past the first centre is f.
float corner_weight(int k, vec2 f) { return ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k >> 1) != 0 ? f.y : 1.0 - f.y); }

// The four pixel centres around a point in continuous pixel coordinates: the first one, and the
// fraction past it (a fraction within 1e-4 of 0 or 1 snaps: a shift by whole pixels takes the
// pixels as they are).
ivec2 corners_around(vec2 at, out vec2 f) {
  f = at - 0.5 - floor(at - 0.5);
  f = mix(f, round(f), lessThan(abs(f - round(f)), vec2(1e-4)));
  return ivec2(floor(at - 0.5));
}

// Whether a record's surface emits (material_emits): beside an emitter a mix read a fraction of
// a pixel off is far off either side.
bool emits(uint record) {
  if (record == kInvalidIndex) return false;
  const uint material = b_geometries[record].materialIndex;
  return b_materials[material].emission_luminance > 0.0 && any(greaterThan(b_materials[material].emission_color, vec3(0.0)));
}

// Whether another record is seen within the pixel's 3x3 neighbourhood of the new view: its
// footprint may mix surfaces.
bool beside_another_surface(uvec2 pixel, uint record) {
  bool mixed = false;
  for (int k = 0; k < 9; ++k) {
    const ivec2 q = ivec2(pixel) + ivec2(k % 3 - 1, k / 3 - 1);
    mixed = mixed || (on_screen(q) && b_gbuffer[texel_index(q)].record != record);
  }
  return mixed;
}

// Whether the old pixel (on screen) shows the record and so do its eight neighbours on screen:
// its value is of that surface alone, not a mix.
bool old_interior(ivec2 from, uint record) {
  bool interior = on_screen(from);
  for (int j = 0; j < 9 && interior; ++j) {
    const ivec2 o = from + ivec2(j % 3 - 1, j / 3 - 1);
    interior = !on_screen(o) || b_previous[texel_index(o)].record == record;
  }
  return interior;
}

// Whether an old pixel shows its surface at about the depth expected of a point of it (the
// background has none).
bool depth_matches(uint record, float depth, uint from) {
  return record == kInvalidIndex || abs(depth / b_previous[from].depth - 1.0) <= 4.0 * u_frame.depthEpsilon;
}

// A pixel beside a silhouette mixes, by its footprint, the surface in front and what lies
// behind; so did the old pixels beside it, and the silhouette moves on screen with the surface
// in front. The pixel takes the old display where that surface's motion carries it (bilinear:
// the mix of a straight edge varies about linearly with a shift under a pixel) when the front
// surface's motion is confirmed (an old pixel around its point shows it at the expected depth),
// every old pixel read shows a surface of the pixel's neighbourhood, and the nearest one the
// pixel's own. False where the pixel is not beside a silhouette, where an emitter borders it
// (its mix read a fraction of a pixel off would be far off), or where a check fails.
bool follow_silhouette(uvec2 pixel, uint record, out vec3 value, out uint samples) {
  value = vec3(0.0);
  samples = 0u;
  uint records[9];
  int count = 0;
  bool mixed = false;
  ivec2 front = ivec2(-1);
  float frontDepth = 3.0e38;
  for (int k = 0; k < 9; ++k) {
    const ivec2 q = ivec2(pixel) + ivec2(k % 3 - 1, k / 3 - 1);
    if (!on_screen(q)) continue;
    const GBufferTexel t = b_gbuffer[texel_index(q)];
    records[count++] = t.record;
    mixed = mixed || t.record != record;
    if (t.record != record && emits(t.record)) return false;
    if (t.record != kInvalidIndex && t.depth < frontDepth) {
      frontDepth = t.depth;
      front = q;
    }
  }
  if (!mixed || front.x < 0) return false;
  const GBufferTexel frontTexel = b_gbuffer[texel_index(front)];
  vec2 frontAt;
  float frontDepthBefore;
  if (!where_before(uvec2(front), frontTexel, frontAt, frontDepthBefore)) return false;
  bool confirmed = false;
  const ivec2 frontBase = ivec2(floor(frontAt - 0.5));
  for (int k = 0; k < 4; ++k) {
    const ivec2 q = frontBase + ivec2(k & 1, k >> 1);
    confirmed = confirmed || (on_screen(q) && b_previous[texel_index(q)].record == frontTexel.record &&
                              depth_matches(frontTexel.record, frontDepthBefore, texel_index(q)));
  }
  if (!confirmed) return false;
  const vec2 at = vec2(pixel) + 0.5 + (frontAt - (vec2(front) + 0.5));
  // The old pixel nearest there must see what the pixel sees through its centre: the surface in
  // front of a curved silhouette (a cushion's top seen edge-on) moves faster than the silhouette
  // itself, and a mix read past it would be of the wrong side.
  const ivec2 nearest = ivec2(floor(at));
  if (!on_screen(nearest) || b_previous[texel_index(nearest)].record != record) return false;
  vec2 f;
  const ivec2 base = corners_around(at, f);
  samples = 0xffffffffu;
  for (int k = 0; k < 4; ++k) {
    const ivec2 corner = base + ivec2(k & 1, k >> 1);
    const float weight = corner_weight(k, f);
    if (weight == 0.0) continue;
    if (!on_screen(corner)) return false;
    const uint seen = b_previous[texel_index(corner)].record;
    bool known = false;
    for (int j = 0; j < count; ++j) known = known || records[j] == seen;
    if (!known) return false;
    value += weight * b_before[texel_index(corner)].shown;
    samples = min(samples, b_before[texel_index(corner)].shownSamples);
  }
  return true;
}

// Near an edge of the old view, where some of the four old pixels around the point are mixes or
// show another surface: the bilinear blend of those that show the pixel's surface alone, at
// about the depth expected, their weights renormalised. False where none does.
bool blend_interior(ivec2 base, vec2 f, uint record, float depth, out vec3 value, out uint samples) {
  value = vec3(0.0);
  samples = 0xffffffffu;
  float total = 0.0;
  for (int k = 0; k < 4; ++k) {
    const ivec2 corner = base + ivec2(k & 1, k >> 1);
    const float weight = corner_weight(k, f);
    if (weight == 0.0 || !old_interior(corner, record) || !depth_matches(record, depth, texel_index(corner))) continue;
    value += weight * b_before[texel_index(corner)].shown;
    samples = min(samples, b_before[texel_index(corner)].shownSamples);
    total += weight;
  }
  value /= max(total, 1e-6);
  return total > 0.0;
}

// What the old view saw of a pixel's surface nearby, for a pixel it did not see there (a
// disocclusion, or one beside an edge): the mean of the old values where the pixel's neighbours
// within two pixels that see the same surface were (the old pixel there shows it at the depth
// expected, and so do the old pixels around it: not a mix). False where no neighbour qualifies.
bool fill_from_surface(uvec2 pixel, uint record, out vec3 value, out uint samples) {
  value = vec3(0.0);
  samples = 0xffffffffu;
  float count = 0.0;
  for (int k = 0; k < 25; ++k) {
    const ivec2 q = ivec2(pixel) + ivec2(k % 5 - 2, k / 5 - 2);
    if (k == 12 || !on_screen(q)) continue;
    const GBufferTexel t = b_gbuffer[texel_index(q)];
    if (t.record != record) continue;
    vec2 at;
    float depth;
    if (!where_before(uvec2(q), t, at, depth)) continue;
    const ivec2 from = ivec2(floor(at));
    if (!old_interior(from, record) || !depth_matches(record, depth, texel_index(from))) continue;
    value += b_before[texel_index(from)].shown;
    samples = min(samples, b_before[texel_index(from)].shownSamples);
    count += 1.0;
  }
  value /= max(count, 1.0);
  return count > 0.0;
}

#endif
