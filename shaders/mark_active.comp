#version 460
// HiPR stage 1, last part: a tile is active when a changed element is visible in it now or
// was before the edit (pixels an object left changed too), or when the screen shows a surface
// the pixel no longer sees (left there by an earlier edit whose tiles were not re-rendered yet:
// the starting point of a drag).
// Reads: both G-buffers, the changed-record flags, the surface each displayed pixel depicts.
// Writes: kTileActive | kTileScored (and kTileFocus where the focus is, kTileLead there and where a
// pixel leads, kTileEditLead there too) into the tile flags, each pixel's bit of the pixel-lead bits, and
// per tile a change score that orders the active tiles: 1 per pixel showing a changed element,
// 2 where the pixel shows another surface than before or than the screen shows (an object moved
// in or out, or another face of it: the largest changes on screen, while a moved object's own
// inside often looks much as it did). A surface is a G-buffer record and the side its geometric
// normal faces (common/octahedral.glsl, surface_turned).
// After a reprojection (a camera edit alone, u_reprojected): the rejected pixels score 2 as
// surfaces shown wrongly, pixels of view-dependent surfaces (kRecordViewDependent: a reflection
// or refraction kept from another view is wrong) 1, so both rank first; every tile is marked
// kTileReprojected, and kTileMoved where a pixel is not kShownStill (schedule_keys.comp renders
// tiles that barely moved last).
// The pixels that lead after an edit (docs/method.md#the-edits-lead) get their bit in the
// pixel-lead bits, every other pixel has it cleared: those whose surface changed (now != before,
// or the screen shows another surface) and, when the edit moved geometry (u_moved: an object
// moved, appeared, disappeared or was deformed), those that show a changed element. Their fresh
// estimate is on screen from its first samples and no difference from the old scene steadies it
// (every path from a moved surface changed), so more samples there lower the displayed error
// most. Their tiles get kTileLead, as the focus's do. Not after a camera edit or one that
// activates every tile: the change is then everywhere.
// The focus (docs/method.md#focus) is marked here too: a pixel whose surface now is a focus
// record, or which lies in a focus disc, makes its tile active and adds its focus weight to the
// tile's focus score. The focus orders tiles after the edit's (schedule_keys.comp) and
// restarts nothing.
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "shared/bindings/visibility.h"
#include "common/dispatch.glsl"
#include "common/octahedral.glsl"

layout(scalar, binding = kMarkActiveGBuffer) readonly buffer GBuffer { GBufferTexel b_gbuffer[]; };
layout(scalar, binding = kMarkActivePrevious) readonly buffer Previous { GBufferTexel b_previous[]; };
layout(scalar, binding = kMarkActiveChangedRecords) readonly buffer Changed { uint b_changed_records[]; };
layout(scalar, binding = kMarkActiveTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kMarkActiveTileChange) buffer TileChange { uint b_tile_change[]; };
layout(scalar, binding = kMarkActiveDisplay) readonly buffer Display { DisplayTexel b_display[]; };
layout(scalar, binding = kMarkActiveFocusDiscs) readonly buffer FocusDiscs { FocusDisc b_focus_discs[]; };
layout(scalar, binding = kMarkActiveTileFocus) buffer TileFocus { uint b_tile_focus[]; };
layout(scalar, binding = kMarkActivePixelLead) buffer PixelLead { uint b_pixel_lead[]; };
// u_everything: the edit activates every tile (carry_tiles.comp did); a surface shown wrongly
// then scores nothing: it is everywhere (a camera move), and would bury the focus's order.
layout(push_constant) uniform Push {
  uint u_focusDiscs;
  uint u_everything;
  uint u_reprojected;
  uint u_moved;
};

bool changed(uint record) { return record != kInvalidIndex && (b_changed_records[record] & kRecordChanged) != 0u; }
bool view_dependent(uint record) { return record != kInvalidIndex && (b_changed_records[record] & kRecordViewDependent) != 0u; }

// The summed focus weight of a pixel: its surface's, and every disc's it lies in.
uint focus_weight(uvec2 pixel, uint record) {
  uint weight = record != kInvalidIndex ? (b_changed_records[record] & ~kRecordViewDependent) >> kFocusWeightShift : 0u;
  const vec2 centre = vec2(pixel) + 0.5;
  for (uint i = 0u; i < min(u_focusDiscs, kMaxFocusDiscs); ++i) {
    const FocusDisc disc = b_focus_discs[i];
    if (distance(centre, disc.center) <= disc.radius) weight += disc.weight;
  }
  return min(weight, kFocusPixelMax);
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_frame.width * u_frame.height) return;
  const uint now = b_gbuffer[index].record, before = b_previous[index].record;
  const uint normal = b_gbuffer[index].normal;
  // Another surface, or another face of the same record (kSurfaceTurnCosine).
  const bool surfaceChanged = now != before || surface_turned(normal, b_previous[index].normal);
  const uint shown = b_display[index].shownRecord;
  const bool wrongSurface = u_everything == 0u && shown != kRecordUnknown &&
                            (shown != now || surface_turned(b_display[index].shownNormal, normal));
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const uint tile = tile_of_pixel(pixel);
  const bool viewChanged = u_reprojected != 0u && !wrongSurface && view_dependent(now);
  if (u_reprojected != 0u)
    atomicOr(b_tile_flags[tile], kTileReprojected | ((b_display[index].flags & kShownStill) == 0u ? kTileMoved : 0u));
  const bool edited = changed(now) || changed(before) || wrongSurface || viewChanged;
  const bool leads = edited && u_everything == 0u && u_reprojected == 0u &&
                     (surfaceChanged || wrongSurface || (u_moved != 0u && changed(now)));
  const uint bit = 1u << (index % 32u);
  if (leads)
    atomicOr(b_pixel_lead[index / 32u], bit);
  else
    atomicAnd(b_pixel_lead[index / 32u], ~bit);
  const uint focus = focus_weight(pixel, now);
  if (!edited && focus == 0u) return;
  atomicOr(b_tile_flags[tile],
           kTileActive | kTileScored | (focus != 0u ? kTileFocus | kTileLead : 0u) | (leads ? kTileLead | kTileEditLead : 0u));
  if (edited) atomicAdd(b_tile_change[tile], surfaceChanged || wrongSurface ? 2u : 1u);
  if (focus != 0u) atomicAdd(b_tile_focus[tile], focus);
}
