// Many-light sampling: walking the light tree (src/render/light_tree.h) from the root to one
// light, each step choosing a child in proportion to a bound on the light it could send to the
// shading point (to its power below a node taken by power), and the probability of that walk
// for a given light (MIS of emitter hits). Only the scene decides both: the same pixel sample
// picks the same light in every schedule.
#ifndef HIPR_LIGHT_TREE_GLSL
#define HIPR_LIGHT_TREE_GLSL

#include "light_tree_cone.glsl"

// cos(max(0, a - b)) from the cosines and sines of a and b (angles in [0, pi]).
float cos_of_gap(float cosA, float sinA, float cosB, float sinB) {
  if (cosA >= cosB) return 1.0;  // a <= b
  return cosA * cosB + sinA * sinB;
}

// How much light a node's lights could send to `position` on a surface with normal `normal`:
// power x the best cosine at the lights (their cone widened by the angle the node's bounding
// sphere subtends) x the best cosine at the surface / squared distance. Zero only where no light
// of the node can emit toward the point (behind one-sided emitters, outside spot cones, behind
// the plane of a node of one-sided surfaces facing one way); the
// surface cosine is floored so that a grazing light is unlikely but never impossible.
float light_tree_importance(LightTreeNode node, vec3 position, vec3 normal) {
  if (!(node.power > 0.0)) return 0.0;
  // Behind every light of a facing node (kLightTreeFacing).
  if (dot(node.axis, position) < light_tree_front(node.cone, node.child)) return 0.0;
  const vec2 cosines = light_tree_cosines(node.cone, node.child);  // theta_o, theta_e
  const vec3 fromCentre = position - node.centre;
  const float d2 = dot(fromCentre, fromCentre);
  // theta_b: half the angle the bounding sphere subtends (everything, from inside it).
  float cosB = -1.0, sinB = 0.0;
  if (d2 > node.radius2) {
    const float sin2 = node.radius2 / d2;
    sinB = sqrt(sin2);
    cosB = sqrt(max(1.0 - sin2, 0.0));
  }
  const vec3 wi = d2 > 0.0 ? fromCentre * inversesqrt(d2) : vec3(0.0, 0.0, 1.0);
  float cosW = clamp(dot(node.axis, wi), -1.0, 1.0);
  if ((node.child & kLightTreeTwoSided) != 0u) cosW = abs(cosW);
  const float sinW = sqrt(max(1.0 - cosW * cosW, 0.0));
  const float sinSpread = sqrt(max(1.0 - cosines.x * cosines.x, 0.0));
  // The angle between the point and the nearest emitting direction: theta_w - theta_o - theta_b.
  const float cosX = cos_of_gap(cosW, sinW, cosines.x, sinSpread);
  const float sinX = sqrt(max(1.0 - cosX * cosX, 0.0));
  const float cosEmit = cos_of_gap(cosX, sinX, cosB, sinB);
  if (cosEmit < cosines.y) return 0.0;
  // At the surface: the light arrives within theta_b of -wi.
  const float cosI = abs(dot(normal, wi));
  const float cosSurface = cos_of_gap(cosI, sqrt(max(1.0 - cosI * cosI, 0.0)), cosB, sinB);
  return node.power * max(cosEmit, 0.0) * max(cosSurface, 1e-3) / max(d2, node.radius2);
}

// The weights of a node's two children at the point (the first at `firstChild`): their
// importances, or their powers below a node taken by power (kLightTreeByPower in `flags`).
vec2 light_tree_weights(uint firstChild, uint flags, vec3 position, vec3 normal) {
  if ((flags & kLightTreeByPower) != 0u) return vec2(b_light_tree[firstChild].power, b_light_tree[firstChild + 1u].power);
  return vec2(light_tree_importance(b_light_tree[firstChild], position, normal),
              light_tree_importance(b_light_tree[firstChild + 1u], position, normal));
}

// Chance of taking `taken` among the two children of a node whose `child` word is `flags`.
float light_tree_branch(uint flags, uint taken, vec3 position, vec3 normal) {
  const uint firstChild = flags & kLightTreeIndexMask;
  const vec2 weights = light_tree_weights(firstChild, flags, position, normal);
  const float first = weights.x, second = weights.y;
  const float sum = first + second;
  if (!(sum > 0.0)) return 0.0;
  return (taken == firstChild ? first : second) / sum;
}

// Walks from the root to a light with `u` in [0, 1) (rescaled at each step); its probability in
// `pmf`. kInvalidIndex where no light of the tree can reach the point.
uint light_tree_pick(vec3 position, vec3 normal, float u, out float pmf) {
  pmf = 1.0;
  uint node = 0u;
  while ((b_light_tree[node].child & kLightTreeLeaf) == 0u) {
    const uint flags = b_light_tree[node].child;
    const uint first = flags & kLightTreeIndexMask;
    const vec2 weights = light_tree_weights(first, flags, position, normal);
    const float a = weights.x, b = weights.y;
    const float sum = a + b;
    if (!(sum > 0.0)) {
      pmf = 0.0;
      return kInvalidIndex;
    }
    const float pFirst = a / sum;
    if (u < pFirst) {
      u = min(u / pFirst, 0.99999994);
      pmf *= pFirst;
      node = first;
    } else {
      const float pSecond = b / sum;
      u = min((u - pFirst) / pSecond, 0.99999994);
      pmf *= pSecond;
      node = first + 1u;
    }
  }
  return b_light_tree[node].child & kLightTreeIndexMask;
}

// The probability that light_tree_pick at this point picks the light whose leaf is `leaf`.
float light_tree_pmf(uint leaf, vec3 position, vec3 normal) {
  float pmf = 1.0;
  uint node = leaf;
  while (b_light_tree[node].parent != kInvalidIndex) {
    const uint parent = b_light_tree[node].parent;
    pmf *= light_tree_branch(b_light_tree[parent].child, node, position, normal);
    node = parent;
  }
  return pmf;
}

#endif
