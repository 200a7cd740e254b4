#version 460
// HiPR stage 1 after a camera edit: what was converged is reused, not restarted. Each pixel's
// stale estimate (and what the screen shows until it is re-rendered) becomes the display before
// the edit, reprojected: the surface point the new G-buffer sees through the pixel centre is
// projected into the camera before the edit (background pixels by direction: the environment
// does not move with the camera), and
//  - accepted: the four old pixels around it show the same record, the ring of twelve around
//    them too (a pixel on an edge mixes surfaces by its footprint, which the new pixel does not
//    share), and its depth is the expected one (1/z interpolated, relative tolerance
//    depthEpsilon as stage 2's): their bilinear blend, with the fewest samples among them;
//  - beside an edge: a same-surface neighbour among the four lies at about that depth: the
//    darkest such value, with a quarter of its samples, for the display rule to judge;
//  - rejected (off-screen before, disoccluded, another surface in front): the darkest of the four
//    (an error too dark is bounded, one too bright is not: an emitter's value never spreads onto
//    the ceiling beside it) until it is rendered; its records say kRecordRejected, so the
//    resolve shows its first fresh samples at once and mark_active.comp ranks its tile first.
// An accepted pixel that moved less than kStillMotion pixels is marked kShownStill: its tile,
// when all its pixels are, is rendered after every other (the per-object "barely moved" rule:
// an object's screen motion is its pixels').
// Kept values are judged by the display rule as any stale value: its bias estimate (D against V)
// decides how long a view-dependent one (a highlight, a reflection) survives its fresh samples.
// No kept samples or light-group shares carry over (they are of other pixels' paths).
// Reads: both G-buffers, the display at the edit (a copy), FrameParams (the new view), the view
// before (push constant). Writes: each pixel's display texel.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "shared/bindings/visibility.h"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"

layout(scalar, binding = kReprojectGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kReprojectPrevious) readonly buffer Previous { GBufferTexel b_previous[]; };
layout(scalar, binding = kReprojectPreviousDisplay) readonly buffer Before { DisplayTexel b_before[]; };
layout(scalar, binding = kReprojectDisplay) buffer Display { DisplayTexel b_display[]; };
layout(push_constant, scalar) uniform Push { ViewFrame u_view; };

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

void main() {
  const uint index = dispatch_index();
  if (index >= u_frame.width * u_frame.height) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const vec3 ray = pixel_centre_ray(pixel);
  const GBufferTexel now = b_gbuffer[index];
  const bool background = now.record == kInvalidIndex;
  const vec3 offset =
      background ? ray : u_frame.cameraPosition + ray * (now.depth / dot(ray, u_frame.cameraForward)) - u_view.position;

  vec2 at;
  float depth;
  const bool inFront = project_before(offset, at, depth);
  // Far off screen (a point near the old camera's plane lands anywhere) is as good as just off
  // it, and stays within what converts to an int.
  at = clamp(at, vec2(-4.0), vec2(u_frame.width + 4u, u_frame.height + 4u));
  // The four pixel centres around the point in the old view, and their bilinear weights (a
  // weight within 1e-4 of 0 or 1 snaps: a shift by whole pixels takes the pixels as they are).
  vec2 f = inFront ? at - 0.5 - floor(at - 0.5) : vec2(0.0);
  f = mix(f, round(f), lessThan(abs(f - round(f)), vec2(1e-4)));
  const ivec2 base = inFront ? ivec2(floor(at - 0.5)) : ivec2(pixel);
  // Accepted when every pixel with a weight is on screen and shows the same record (a pixel on
  // an edge between surfaces mixes them by its footprint, which another view does not share: it
  // is rendered again instead), and the point's depth is the one expected there: the old depths'
  // 1/z interpolated (exact across a plane, where z itself is not: a grazing floor's depth
  // changes fast from pixel to pixel).
  bool accepted = inFront;
  vec3 value = vec3(0.0);
  float inverseDepth = 0.0;
  uint samples = 0xffffffffu;
  // A hole's value until it is rendered: the darkest of the four on screen, of the same surface
  // where one is. An error by a value too dark is bounded (relMSE at most 1/2 per pixel), one
  // too bright is not: never an emitter's value spread onto the ceiling beside it.
  uint fill = kInvalidIndex;
  float fillLuminance = 3.0e38;
  bool fillSameRecord = false;
  for (int k = 0; k < 4 && inFront; ++k) {
    const ivec2 corner = base + ivec2(k & 1, k >> 1);
    const float weight = ((k & 1) != 0 ? f.x : 1.0 - f.x) * ((k >> 1) != 0 ? f.y : 1.0 - f.y);
    if (corner.x < 0 || corner.y < 0 || corner.x >= int(u_frame.width) || corner.y >= int(u_frame.height)) {
      accepted = accepted && weight == 0.0;
      continue;
    }
    const uint from = uint(corner.y) * u_frame.width + uint(corner.x);
    const bool same = b_previous[from].record == now.record;
    const float lum = dot(b_before[from].shown, vec3(0.2126, 0.7152, 0.0722));
    if ((same && !fillSameRecord) || (same == fillSameRecord && lum < fillLuminance)) {
      fill = from;
      fillLuminance = lum;
      fillSameRecord = same;
    }
    if (weight == 0.0) continue;
    accepted = accepted && same;
    inverseDepth += weight / b_previous[from].depth;
    value += weight * b_before[from].shown;
    samples = min(samples, b_before[from].shownSamples);
  }
  if (accepted && !background) accepted = abs(depth * inverseDepth - 1.0) <= u_frame.depthEpsilon;
  // An old pixel next to another surface may cover part of it (a converged edge pixel is a mix,
  // by its footprint): the ring of pixels around the four must show the same record too. Near
  // an emitter's edge a mix is far off either side.
  for (int k = 0; k < 16 && accepted; ++k) {
    const ivec2 corner = base + ivec2(k % 4 - 1, k / 4 - 1);
    if (k % 4 != 0 && k % 4 != 3 && k / 4 != 0 && k / 4 != 3) continue;  // the four themselves
    if (corner.x < 0 || corner.y < 0 || corner.x >= int(u_frame.width) || corner.y >= int(u_frame.height)) continue;
    accepted = b_previous[uint(corner.y) * u_frame.width + uint(corner.x)].record == now.record;
  }

  // Beside an edge, where a neighbour of the same surface is at about the depth expected: its
  // value (the darkest such) is kept, with a quarter of its samples, for the display rule to
  // judge against the fresh ones, rather than rejected (shown fresh and noisy at once).
  const bool besideEdge = !accepted && fillSameRecord &&
                          (background || abs(depth / b_previous[fill].depth - 1.0) <= 4.0 * u_frame.depthEpsilon);

  DisplayTexel texel;
  if (accepted) {
    texel.shown = value;
    texel.shownSamples = samples;
    texel.shownRecord = now.record;
  } else if (besideEdge) {
    texel.shown = b_before[fill].shown;
    texel.shownSamples = b_before[fill].shownSamples / 4u;
    texel.shownRecord = now.record;
  } else {
    // Off-screen or behind the old camera: the old view's nearest pixel, or the pixel itself.
    if (fill == kInvalidIndex) {
      const uvec2 nearest = inFront ? uvec2(clamp(at, vec2(0.0), vec2(u_frame.width - 1u, u_frame.height - 1u))) : pixel;
      fill = nearest.y * u_frame.width + nearest.x;
    }
    texel.shown = b_before[fill].shown;
    texel.shownSamples = 0u;
    texel.shownRecord = kRecordRejected;
  }
  texel.stale = texel.shown;
  texel.staleSamples = texel.shownSamples;
  texel.staleRecord = texel.shownRecord;
  // Where the surface barely moved on screen the kept value is nearly the pixel's own: stage 1
  // ranks tiles of such pixels last.
  const vec2 motion = at - (vec2(pixel) + 0.5);
  texel.flags = accepted && inFront && dot(motion, motion) < kStillMotion * kStillMotion ? kShownStill : 0u;
  b_display[index] = texel;
}
