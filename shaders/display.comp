#version 460
// The viewer's display pass: what the window shows under the UI. Each window pixel takes the
// nearest rendered pixel of the displayed image (placed and scaled by the push constants),
// tone-maps it exactly as tonemap_srgb8 does (exposure, tone mapper, sRGB curve, 8 bits) and blends
// the overlay on top in display space; pixels outside the image get the background colour.
// Reads: the display (DisplayTexel.shown, where the resolve wrote it: no copy through the host)
// or the denoiser's copy of it (vec3), the overlay. Writes: one RGBA8 word per window pixel.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "shared/bindings/display.h"
#include "common/dispatch.glsl"
#include "common/srgb.glsl"
#include "common/tone_mappers.glsl"

layout(scalar, binding = kDisplayTexels) readonly buffer Source { float b_source[]; };
layout(scalar, binding = kDisplayOverlay) readonly buffer Overlay { uint b_overlay[]; };
layout(scalar, binding = kDisplayOutput) writeonly buffer Output { uint b_output[]; };
layout(push_constant, scalar) uniform Push { DisplayPush u_push; };

void main() {
  const uint index = dispatch_index();
  if (index >= u_push.outputWidth * u_push.outputHeight) return;
  const vec2 window = vec2(index % u_push.outputWidth, index / u_push.outputWidth) + 0.5;
  const vec2 source = floor((window - vec2(u_push.viewX, u_push.viewY)) / u_push.viewScale);
  if (any(lessThan(source, vec2(0.0))) || source.x >= float(u_push.sourceWidth) ||
      source.y >= float(u_push.sourceHeight)) {
    b_output[index] = u_push.background;
    return;
  }
  const uint pixel = uint(source.y) * u_push.sourceWidth + uint(source.x);
  const uint at = pixel * u_push.sourceStride;
  const vec3 exposed = vec3(b_source[at], b_source[at + 1u], b_source[at + 2u]) * u_push.exposureScale;
  // The clamp mapper stays per channel, bit for bit what it always was.
  uvec3 rgb = srgb_bytes(u_push.toneMapper == kToneClamp ? exposed
                                                         : tone_map(exposed, u_push.toneMapper));
  if (u_push.overlayEnabled != 0u) {
    const uint overlay = b_overlay[pixel];
    const float alpha = float(overlay >> 24u) / 255.0;
    const vec3 colour = vec3(overlay & 0xffu, (overlay >> 8u) & 0xffu, (overlay >> 16u) & 0xffu);
    rgb = uvec3(floor(mix(vec3(rgb), colour, alpha) + 0.5));
  }
  b_output[index] = rgb.r | (rgb.g << 8u) | (rgb.b << 16u) | (255u << 24u);
}
