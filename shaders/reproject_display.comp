#version 460
// HiPR stage 1 after a camera edit: what was converged is reused, not restarted. Each pixel's
// stale estimate (and what the screen shows until it is re-rendered) becomes the display before
// the edit, reprojected: the surface point the new G-buffer sees through the pixel centre is
// projected into the camera before the edit (background pixels by direction: the environment
// does not move with the camera), and the first of these that holds gives its value
// (common/reprojection.glsl has the estimates):
//  - accepted: the four old pixels around it show the same record, the ring of twelve around
//    them too (a pixel on an edge mixes surfaces by its footprint, which the new pixel does not
//    share), and its depth is the expected one (1/z interpolated, relative tolerance
//    depthEpsilon as stage 2's): their bilinear blend, with the fewest samples among them;
//  - beside a silhouette (another surface in its 3x3 neighbourhood): the old mix where the
//    surface in front carried the silhouette, or the pixel's own reading where that is darker
//    (a curved silhouette moves slower than its surface);
//  - near an old edge: the blend of those of the four that show its surface alone, or else the
//    darkest of the four that shows its surface at about the depth expected;
//  - rejected (off-screen before, disoccluded, another surface in front): what the old view saw
//    of its surface nearby, or the darkest of the four, until it is rendered; its records say
//    kRecordRejected, so the resolve shows its first fresh samples at once and
//    mark_active.comp ranks its tile first.
// Values beside and near edges keep a quarter of their samples, for the display rule to judge
// against the fresh ones rather than show them, noisy, at once. An error too dark is bounded,
// one too bright is not: where the pixel or a neighbour emits, no pure value stands for a mix.
// An accepted pixel that moved less than kStillMotion pixels is marked kShownStill: its tile,
// when all its pixels are, is rendered after every other (the per-object "barely moved" rule:
// an object's screen motion is its pixels').
// Kept values are judged by the display rule as any stale value: its bias estimate (D against V)
// decides how long a view-dependent one (a highlight, a reflection) survives its fresh samples.
// No kept samples or light-group shares carry over (they are of other pixels' paths).
// Reads: both G-buffers, the display at the edit (a copy), FrameParams (the new view), the view
// before (push constant), the scene's records and materials (which emit). Writes: each pixel's
// display texel.
#extension GL_GOOGLE_include_directive : require
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "common/scene_bindings.glsl"
#include "shared/bindings/visibility.h"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"

layout(scalar, binding = kReprojectGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kReprojectPrevious) readonly buffer Previous { GBufferTexel b_previous[]; };
layout(scalar, binding = kReprojectPreviousDisplay) readonly buffer Before { DisplayTexel b_before[]; };
layout(scalar, binding = kReprojectDisplay) buffer Display { DisplayTexel b_display[]; };
layout(push_constant, scalar) uniform Push { ViewFrame u_view; };

#include "common/reprojection.glsl"

void main() {
  const uint index = dispatch_index();
  if (index >= u_frame.width * u_frame.height) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const GBufferTexel now = b_gbuffer[index];
  const bool background = now.record == kInvalidIndex;
  vec2 at;
  float depth;
  const bool inFront = where_before(pixel, now, at, depth);
  vec2 f = vec2(0.0);
  const ivec2 base = inFront ? corners_around(at, f) : ivec2(pixel);
  // Accepted when every pixel with a weight is on screen and shows the same record (a pixel on
  // an edge between surfaces mixes them by its footprint, which another view does not share),
  // and the point's depth is the one expected there: the old depths' 1/z interpolated (exact
  // across a plane, where z itself is not: a grazing floor's depth changes fast from pixel to
  // pixel).
  bool accepted = inFront;
  bool whole = inFront;  // every pixel with a weight on screen and of the surface: `value` is theirs
  vec3 value = vec3(0.0);
  float inverseDepth = 0.0;
  uint samples = 0xffffffffu;
  // The darkest of the four on screen, of the same surface where one is: the last resort (an
  // error too dark is bounded, relMSE at most 1/2 per pixel; one too bright is not).
  uint fill = kInvalidIndex;
  float fillLuminance = 3.0e38;
  bool fillSameRecord = false;
  for (int k = 0; k < 4 && inFront; ++k) {
    const ivec2 corner = base + ivec2(k & 1, k >> 1);
    const float weight = corner_weight(k, f);
    if (!on_screen(corner)) {
      accepted = accepted && weight == 0.0;
      whole = whole && weight == 0.0;
      continue;
    }
    const uint from = texel_index(corner);
    const bool same = b_previous[from].record == now.record;
    const float lum = dot(b_before[from].shown, kLuma);
    if ((same && !fillSameRecord) || (same == fillSameRecord && lum < fillLuminance)) {
      fill = from;
      fillLuminance = lum;
      fillSameRecord = same;
    }
    if (weight == 0.0) continue;
    accepted = accepted && same;
    whole = whole && same;
    inverseDepth += weight / b_previous[from].depth;
    value += weight * b_before[from].shown;
    samples = min(samples, b_before[from].shownSamples);
  }
  if (accepted && !background) accepted = abs(depth * inverseDepth - 1.0) <= u_frame.depthEpsilon;
  // An old pixel next to another surface may cover part of it (a converged edge pixel is a mix,
  // by its footprint): the ring of pixels around the four must show the same record too.
  for (int k = 0; k < 16 && accepted; ++k) {
    const ivec2 corner = base + ivec2(k % 4 - 1, k / 4 - 1);
    if (k % 4 != 0 && k % 4 != 3 && k / 4 != 0 && k / 4 != 3) continue;  // the four themselves
    if (on_screen(corner)) accepted = b_previous[texel_index(corner)].record == now.record;
  }

  DisplayTexel texel;
  texel.shownRecord = now.record;
  texel.shownNormal = now.normal;
  vec3 estimate;
  uint estimateSamples;
  // A pure value of the pixel's surface may stand for it unless it emits beside another surface
  // (its true value is a mix, far darker). Not looked up for accepted pixels, which need no such
  // value.
  const bool pureIsSafe = accepted || !(emits(now.record) && beside_another_surface(pixel, now.record));
  if (accepted) {
    texel.shown = value;
    texel.shownSamples = samples;
  } else if (follow_silhouette(pixel, now.record, estimate, estimateSamples)) {
    texel.shown = whole && dot(value, kLuma) < dot(estimate, kLuma) ? value : estimate;
    texel.shownSamples = estimateSamples / 4u;
  } else if (inFront && pureIsSafe && blend_interior(base, f, now.record, depth, estimate, estimateSamples)) {
    texel.shown = estimate;
    texel.shownSamples = estimateSamples / 4u;
  } else if (fillSameRecord && depth_matches(now.record, depth, fill)) {
    texel.shown = b_before[fill].shown;
    texel.shownSamples = b_before[fill].shownSamples / 4u;
  } else {
    // Rejected: what the old view saw of the surface nearby; failing that the darkest of the
    // four, or off-screen or behind the old camera the old view's nearest pixel, or the pixel
    // itself.
    if (fill == kInvalidIndex) {
      const uvec2 nearest = inFront ? uvec2(clamp(at, vec2(0.0), vec2(u_frame.width - 1u, u_frame.height - 1u))) : pixel;
      fill = nearest.y * u_frame.width + nearest.x;
    }
    const bool nearby = pureIsSafe && fill_from_surface(pixel, now.record, estimate, estimateSamples);
    texel.shown = nearby ? estimate : b_before[fill].shown;
    texel.shownSamples = 0u;
    texel.shownRecord = kRecordRejected;
    texel.shownNormal = kNormalUnknown;
  }
  texel.stale = texel.shown;
  texel.staleSamples = texel.shownSamples;
  texel.staleRecord = texel.shownRecord;
  texel.staleNormal = texel.shownNormal;
  texel.screenNoise = 1.0;  // not filtered in this view yet
  // Where the surface barely moved on screen the kept value is nearly the pixel's own: stage 1
  // ranks tiles of such pixels last.
  const vec2 motion = at - (vec2(pixel) + 0.5);
  texel.flags = accepted && inFront && dot(motion, motion) < kStillMotion * kStillMotion ? kShownStill : 0u;
  b_display[index] = texel;
}
