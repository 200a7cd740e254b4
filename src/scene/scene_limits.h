#pragma once
// What a scene may hold for the renderer to derive its world-space quantities (the BVHs' boxes,
// the light tables' powers, the camera and the projections) in float arithmetic without
// overflow: checked once where a scene is loaded and after every edit that could break it
// (docs/method.md#limits).
#include <string>

#include "hipr/edits.h"
#include "hipr/scene.h"

namespace hipr {

// No world coordinate (a vertex, a light, the camera) beyond this many metres from the origin:
// a million kilometres. Areas then stay below 1e19 and their sums below the float range.
inline constexpr float kMaxWorldCoordinate = 1e9f;
// No emission luminance (nits), punctual light intensity (cd or lux) or environment intensity
// beyond this: about 600 times the sun's disc (1.6e9 nits).
inline constexpr float kMaxRadiance = 1e12f;

// Throws InputError ("`what`: ...", one line naming the node, light or material) when a
// transform or value of the scene is not finite or beyond the limits above. With
// `geometry` false only lights, materials, the environment and the camera are checked (no
// vertex is read).
void check_scene_limits(const Scene& scene, const std::string& what, bool geometry = true);

// Throws InputError when an edit sets a light, emission or environment intensity beyond
// kMaxRadiance (checked before it is applied).
// The message names the edit (describe), made only when it is refused.
void check_edit_values(const Edit& edit);

// Whether an edit can move or reshape geometry (and so needs check_scene_limits' geometry part).
bool edit_moves_geometry(const Edit& edit);

}  // namespace hipr
