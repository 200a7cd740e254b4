#version 460
// The display denoiser's keys: for each pixel, which neighbours it may mix with (keys_mix in
// common/denoise.glsl), or kDenoiseKept where it is shown as it is. A kernel of their own, run
// before denoise_prepare.comp: the variance of a pixel with few samples is taken over the 3 x 3
// neighbours its key mixes with, and computed there, each of the nine keys scanned its own 3 x 3
// guides again (81 guide reads a pixel; prepare took 0.164 s of the filter's 0.50 s on the Cornell
// box at 512 x 512 and 1 spp, against 0.019 s at 4 spp, where no pixel needs it).
// Neighbours mix only when they show the same surface (the G-buffer record their guide
// ray hit) and, with the display state, values of the same scene state (a stale pixel and a fresh
// one never mix: the filter does not spread a change, or the absence of one, across the line the
// re-render has reached; a re-rendered pixel showing its stale estimate, unchanged, mixes with
// either: scene_state). A pixel whose shown value depicts another surface than the one its
// guide sees (a moved object's old place, still stale) is kept as it is and read by no one.
// A pixel beside an edge (a neighbour sees another surface, a normal or plane of its own, another
// albedo) mixes two surfaces in its samples, though its centre sees one: it takes and gives only
// among pixels beside edges too (kDenoiseBoundary). Filtered with the inside of its surface, an
// edge lost its antialiasing and a bright emitter's rim bled along the surface beside it.
// Reads: the guides, the display (shown value, its record and scene state), FrameParams (the
// pixel rays). Writes: the key of every pixel.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "common/denoise.glsl"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"

layout(scalar, binding = kDenoiseGuides) readonly buffer Guides { DenoiseGuide b_guides[]; };
layout(scalar, binding = kDenoiseDisplay) readonly buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kDenoiseKeys) writeonly buffer Keys { uint b_keys[]; };
layout(push_constant, scalar) uniform Push { DenoisePush u_push; };

const float kEdgeNormalCosine = 0.9;   // normals further apart: an edge (about 25 degrees)
const float kEdgePlane = 0.1;           // a neighbour further off the tangent plane (as a slope)
const float kEdgeAlbedo = 0.1;          // an albedo further off in any channel

vec3 guide_position(uvec2 pixel, DenoiseGuide guide) {
  return u_frame.cameraPosition + pixel_centre_ray(pixel) * guide.distance;
}

// Whether a neighbour of the pixel sees another surface, or the same one across an edge of its
// own (a fold, a corner) or of its albedo.
bool beside_edge(uvec2 pixel, DenoiseGuide guide) {
  const bool surface = guide.record != kInvalidIndex;
  const vec3 normal = surface ? unpack_normal(guide.normal) : vec3(0.0);
  const vec3 position = surface ? guide_position(pixel, guide) : vec3(0.0);
  const vec3 albedo = unpackUnorm4x8(guide.albedo).rgb;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const ivec2 q = ivec2(pixel) + ivec2(dx, dy);
      if ((dx == 0 && dy == 0) || any(lessThan(q, ivec2(0))) || q.x >= int(u_push.width) || q.y >= int(u_push.height))
        continue;
      const DenoiseGuide other = b_guides[uint(q.y) * u_push.width + uint(q.x)];
      if (other.record != guide.record) return true;
      if (any(greaterThan(abs(unpackUnorm4x8(other.albedo).rgb - albedo), vec3(kEdgeAlbedo)))) return true;
      if (!surface) continue;
      if (dot(unpack_normal(other.normal), normal) < kEdgeNormalCosine) return true;
      const vec3 offset = guide_position(uvec2(q), other) - position;
      if (abs(dot(normal, offset)) > kEdgePlane * length(offset)) return true;
    }
  return false;
}

// The scene state of the pixel's key: the scene before the last edit (no bit), since it
// (kDenoiseCurrent), or unchanged (kDenoiseUnchanged): a re-rendered pixel whose fresh samples
// found no change, the difference rule showing its stale estimate bit for bit. That value is what
// the pixels not re-rendered yet show and what the re-rendered ones estimate where nothing
// changed: it mixes with either. Kept apart from the first, the line the re-render had reached
// cut the filter's footprint in every tile it crossed (CornellBox's walls grew noisier on the
// screen where a moved sphere changed nothing); apart from the second, such a pixel inside a
// change (colour bleeding its two samples missed) no longer took its neighbours' change.
uint scene_state(DisplayTexel texel) {
  if (!shows_current(texel, u_push.displayState)) return 0u;
  const bool unchanged = u_push.displayState != 0u && (texel.flags & kStaleCurrent) == 0u && texel.staleSamples > 0u &&
                         all(equal(texel.shown, texel.stale));
  return unchanged ? kDenoiseUnchanged : kDenoiseCurrent;
}

uint pixel_key(uint index) {
  const DisplayTexel texel = b_display[index];
  const uint seen = b_guides[index].record;
  if (u_push.strength <= 0.0 || any(isinf(texel.shown)) || any(isnan(texel.shown)) ||
      any(isinf(unpack_emission(b_guides[index]))))
    return kDenoiseKept;
  // (Behind a veil the record a value was rendered with may be the veil's or the guide's.)
  if (u_push.displayState != 0u && texel.shownRecord != kRecordUnknown && texel.shownRecord != seen &&
      !guide_veiled(b_guides[index]))
    return kDenoiseKept;
  // The environment seen directly has no noise but its antialiasing: nothing to filter.
  if (seen == kInvalidIndex) return kDenoiseKept;
  const uint surface = (seen + 1u) & kDenoiseSurfaceMask;
  const uvec2 pixel = uvec2(index % u_push.width, index / u_push.width);
  return surface | scene_state(texel) |
         (beside_edge(pixel, b_guides[index]) ? kDenoiseBoundary : 0u);
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_push.width * u_push.height) return;
  b_keys[index] = pixel_key(index);
}
