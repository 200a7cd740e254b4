#version 460
// The viewer's overlays, made on the GPU from what the renderer holds there, so showing them
// costs no read-back: object ids from the G-buffer, stage 2's tile weights as a heat map (active
// tiles blue), the tiles still owed a restart, and the selected node's outline on top. The
// colours are image/debug_images.cpp's (what `hipr replay` writes): the id colour's hash is the
// same, its channels' sRGB bytes come from a table the host made with the same functions, so the
// ids overlay matches the CPU's byte for byte.
// Pass 0 (one invocation per tile): the largest tile weight, which the heat map is relative to.
// Pass 1 (one per pixel): the overlay word.
// Reads: G-buffer, record table, tile weights and flags, the accumulation's owed bits.
// Writes: one RGBA8 word per rendered pixel (sRGB colour, alpha = coverage); the largest weight.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require
#extension GL_EXT_shader_atomic_int64 : require

layout(local_size_x = 64) in;

#include "shared/bindings/overlay.h"
#include "common/dispatch.glsl"
#include "common/srgb.glsl"

layout(scalar, binding = kOverlayGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kOverlayRecords) readonly buffer Records { OverlayRecord b_records[]; };
layout(scalar, binding = kOverlayTileWeights) readonly buffer TileWeights { uint64_t b_tile_weights[]; };
layout(scalar, binding = kOverlayTileFlags) readonly buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kOverlayAccumulation) readonly buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kOverlayIdBytes) readonly buffer IdBytes { uint b_id_bytes[]; };
layout(scalar, binding = kOverlayMaxWeight) buffer MaxWeight { uint64_t b_max_weight; };
layout(scalar, binding = kOverlayOutput) writeonly buffer Output { uint b_output[]; };
layout(push_constant, scalar) uniform Push { OverlayPush u_push; };

// Coverages and display-space colours of app/viewer/overlays.cpp: the heat map stays readable
// over the picture, the owed tint (sRGB 0.95, 0.1, 0.75) does not hide it; the outline is sRGB
// (1, 0.6, 0.1).
const float kWeightCoverage = 0.7;
const float kOwedCoverage = 0.45;

uint pack_rgba8(uvec3 rgb, float coverage) { return rgb.r | (rgb.g << 8u) | (rgb.b << 16u) | (srgb_byte(coverage) << 24u); }

// debug_images.cpp's id_colour: the hash picks a byte per channel, the table its sRGB byte.
uvec3 id_bytes(uint id) {
  uint h = id * 2654435761u + 0x9e3779b9u;
  h ^= h >> 15u;
  h *= 0x2c1b3c6du;
  h ^= h >> 12u;
  return uvec3(b_id_bytes[h & 0xffu], b_id_bytes[(h >> 8u) & 0xffu], b_id_bytes[(h >> 16u) & 0xffu]);
}

// debug_images.cpp's heat_colour: black -> red -> yellow -> white.
vec3 heat_colour(float v) { return vec3(min(1.0, 3.0 * v), clamp(3.0 * v - 1.0, 0.0, 1.0), clamp(3.0 * v - 2.0, 0.0, 1.0)); }

uint node_at(int x, int y) {
  if (x < 0 || y < 0 || x >= int(u_push.width) || y >= int(u_push.height)) return kInvalidIndex;
  const uint record = b_gbuffer[uint(y) * u_push.width + uint(x)].record;
  return record == kInvalidIndex ? kInvalidIndex : b_records[record].node;
}

void main() {
  const uint index = dispatch_index();
  if (u_push.pass == 0u) {
    if (index < u_push.tileCount) atomicMax(b_max_weight, b_tile_weights[index]);
    return;
  }
  if (index >= u_push.width * u_push.height) return;
  const uint x = index % u_push.width, y = index / u_push.width;
  const uint tile = (y / u_push.tileSize) * u_push.tilesX + x / u_push.tileSize;
  uint word = 0u;
  if (u_push.mode == kOverlayIds) {
    const uint record = b_gbuffer[index].record;
    word = record == kInvalidIndex ? pack_rgba8(uvec3(0u), 1.0) : pack_rgba8(id_bytes(b_records[record].instance), 1.0);
  } else if (u_push.mode == kOverlayWeights) {
    vec3 colour = vec3(0.0);
    const uint64_t weight = b_tile_weights[tile];
    if ((b_tile_flags[tile] & kTileActive) != 0u)
      colour = vec3(0.1, 0.3, 1.0);
    else if (weight > 0ul)  // a log scale over six decades below the largest (log10 = log2 x 0.30103)
      colour = heat_colour(clamp(1.0 + log2(float(weight) / float(b_max_weight)) * (0.30103 / 6.0), 0.0, 1.0));
    word = pack_rgba8(srgb_bytes(colour), kWeightCoverage);
  } else if (u_push.mode == kOverlayOwed) {
    // Tiles render whole: a pixel owes its restart exactly when its tile does.
    if ((b_accum[index].count & kPixelOwed) != 0u) word = pack_rgba8(uvec3(242u, 26u, 191u), kOwedCoverage);
  }
  if (u_push.selectedNode != kInvalidIndex) {
    const int ix = int(x), iy = int(y);
    if (node_at(ix, iy) == u_push.selectedNode &&
        (node_at(ix - 1, iy) != u_push.selectedNode || node_at(ix + 1, iy) != u_push.selectedNode ||
         node_at(ix, iy - 1) != u_push.selectedNode || node_at(ix, iy + 1) != u_push.selectedNode))
      word = pack_rgba8(uvec3(255u, 153u, 26u), 1.0);
  }
  b_output[index] = word;
}
