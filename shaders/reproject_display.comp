#version 460
// HiPR stage 1 after a camera edit: what was converged is reused, not restarted. Each pixel's
// stale estimate (and what the screen shows until it is re-rendered) becomes the display before
// the edit, reprojected: the surface point the new G-buffer sees through the pixel centre is
// projected into the camera before the edit, and the pixel there is taken (nearest) when the
// G-buffer before the edit shows the same record there at the expected depth (relative tolerance
// depthEpsilon, as stage 2's projection). Background pixels reproject by direction (the
// environment does not move with the camera) onto background pixels. Elsewhere (off-screen
// before, disoccluded, another surface in front) the pixel is rejected: it still shows the
// nearest value the old view has (a hole filled, not black) but its records say kRecordRejected,
// so the resolve shows its first fresh samples at once and mark_active.comp ranks its tile first.
// Accepted values keep their sample counts: the display rule's bias estimate (D against V) then
// decides how long a view-dependent value (a highlight, a reflection) survives its fresh samples.
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

layout(scalar, binding = kReprojectGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kReprojectPrevious) readonly buffer Previous { GBufferTexel b_previous[]; };
layout(scalar, binding = kReprojectPreviousDisplay) readonly buffer Before { DisplayTexel b_before[]; };
layout(scalar, binding = kReprojectDisplay) buffer Display { DisplayTexel b_display[]; };
layout(push_constant, scalar) uniform Push { ViewFrame u_view; };

// Where `offset` (a point minus the old camera's position, or a direction) lands in the old
// view: continuous pixel coordinates and the depth along its axis; false behind the camera.
bool project_before(vec3 offset, out vec2 pixel, out float depth) {
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
  const vec2 ndc = (vec2(pixel) + 0.5) / vec2(u_frame.width, u_frame.height) * 2.0 - 1.0;
  const vec3 ray = normalize(u_frame.cameraForward + ndc.x * u_frame.tanHalfFovY * u_frame.aspect * u_frame.cameraRight -
                             ndc.y * u_frame.tanHalfFovY * u_frame.cameraUp);
  const GBufferTexel now = b_gbuffer[index];
  const bool background = now.record == kInvalidIndex;
  const vec3 offset =
      background ? ray : u_frame.cameraPosition + ray * (now.depth / dot(ray, u_frame.cameraForward)) - u_view.position;

  vec2 at;
  float depth;
  const bool inFront = project_before(offset, at, depth);
  const bool onScreen = inFront && at.x >= 0.0 && at.y >= 0.0 && at.x < float(u_frame.width) && at.y < float(u_frame.height);
  // The pixel taken: where the point was, else (behind the old camera) the pixel itself.
  const uvec2 source = inFront ? uvec2(clamp(at, vec2(0.0), vec2(u_frame.width - 1u, u_frame.height - 1u))) : pixel;
  const uint from = source.y * u_frame.width + source.x;
  bool accepted = false;
  if (onScreen) {
    const GBufferTexel before = b_previous[from];
    accepted = before.record == now.record &&
               (background || abs(depth - before.depth) <= u_frame.depthEpsilon * before.depth);
  }

  const DisplayTexel old = b_before[from];
  DisplayTexel texel;
  texel.shown = old.shown;
  texel.stale = old.shown;
  texel.shownSamples = accepted ? old.shownSamples : 0u;
  texel.staleSamples = texel.shownSamples;
  texel.shownRecord = accepted ? now.record : kRecordRejected;
  texel.staleRecord = texel.shownRecord;
  texel.flags = 0u;
  b_display[index] = texel;
}
