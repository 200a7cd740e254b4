// A light tree node's `cone` word (shared/abi.h, LightTreeNode), decoded. Shared with C++
// (shared/glsl_cpp.h): the builder's checks and tests read a node through these very functions.
#ifndef HIPR_LIGHT_TREE_CONE_GLSL
#define HIPR_LIGHT_TREE_CONE_GLSL

#include "../shared/glsl_cpp.h"

// cos theta_o (x) and cos theta_e (y) of a node whose `child` word is `flags`. A facing node's
// lights all face its axis: theta_o 0, theta_e 90 degrees.
HIPR_FN vec2 light_tree_cosines(uint cone, uint flags) {
  if ((flags & kLightTreeFacing) != 0u) return vec2(1.0f, 0.0f);
  return unpackUnorm2x16(cone) * 2.0f - 1.0f;
}

// The plane of a facing node (its lights lie where dot(axis, y) >= front); -inf: none.
HIPR_FN float light_tree_front(uint cone, uint flags) {
  return (flags & kLightTreeFacing) != 0u ? uintBitsToFloat(cone) : uintBitsToFloat(0xff800000u);
}

#endif
