// Software traversal of the two-level BVH in the scene's set (abi BvhNode, BvhTriangle,
// BvhInstance; built by src/render/software_bvh.cpp): the top level over visible instances in
// world space, one BVH per mesh in object space. Nearer child first, an explicit stack per
// level (the builder keeps trees at most kBvhMaxDepth deep). It reports what a ray query
// would: the record, primitive, barycentrics, t along the world-space ray and the instance's
// transforms; candidates of cutout geometry are confirmed by cutout_hit, like the ray-query
// path's candidate loop. Included by scene_trace.glsl.
#ifndef HIPR_BVH_TRAVERSAL_GLSL
#define HIPR_BVH_TRAVERSAL_GLSL

const uint kBvhStackSize = kBvhMaxDepth + 2u;

// 1/d with zero components replaced by tiny ones of the same sign: slab distances stay finite
// (0 x inf would be NaN) and an axis-parallel ray still misses boxes beside it.
vec3 bvh_inverse_direction(vec3 d) {
  const vec3 safe = mix(d, vec3(1.0e-30) * (vec3(1.0) - 2.0 * vec3(lessThan(d, vec3(0.0)))),
                        lessThan(abs(d), vec3(1.0e-30)));
  return 1.0 / safe;
}

// Entry distance of the ray into the box, or -1 when it misses it within [0, tMax]. The exit
// is widened by a few ulps, so a triangle lying in a box face is not lost to rounding.
float bvh_box_entry(BvhNode node, vec3 origin, vec3 inverseDirection, float tMax) {
  const vec3 t0 = (node.lo - origin) * inverseDirection;
  const vec3 t1 = (node.hi - origin) * inverseDirection;
  const vec3 near = min(t0, t1);
  const vec3 far = max(t0, t1);
  const float enter = max(max(near.x, max(near.y, near.z)), 0.0);
  const float exit = min(min(far.x, min(far.y, far.z)) * 1.0000004, tMax);
  return enter <= exit ? enter : -1.0;
}

// A ray prepared for the watertight triangle test (Woop, Benthin and Wald, JCGT 2013): axes
// permuted so the direction's largest component is z, and the shear that makes it (0, 0, 1).
struct BvhShearedRay {
  vec3 origin;
  ivec3 axes;  // x, y, z after the permutation
  vec3 shear;  // -dx/dz, -dy/dz, 1/dz
};

BvhShearedRay bvh_sheared_ray(vec3 origin, vec3 direction) {
  const vec3 a = abs(direction);
  const int kz = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
  int kx = (kz + 1) % 3, ky = (kz + 2) % 3;
  if (direction[kz] < 0.0) {  // keep the winding: swap x and y
    const int swap = kx;
    kx = ky;
    ky = swap;
  }
  return BvhShearedRay(origin, ivec3(kx, ky, kz),
                       vec3(direction[kx] / direction[kz], direction[ky] / direction[kz], 1.0 / direction[kz]));
}

// Watertight: a ray through an edge (or a vertex) shared by two triangles hits at least one of
// them, whatever the rounding, since both evaluate that edge's function from the same two sheared
// vertices and get exactly opposite values (the kernels forbid FMA contraction, which would break
// this). Both faces; t in [0, tMax); the barycentrics of v1 and v2.
bool bvh_triangle_hit(BvhTriangle tri, BvhShearedRay ray, float tMax, out float t, out vec2 bary) {
  const vec3 a = tri.v0 - ray.origin, b = tri.v1 - ray.origin, c = tri.v2 - ray.origin;
  const ivec3 k = ray.axes;
  const vec2 as = vec2(a[k.x] - ray.shear.x * a[k.z], a[k.y] - ray.shear.y * a[k.z]);
  const vec2 bs = vec2(b[k.x] - ray.shear.x * b[k.z], b[k.y] - ray.shear.y * b[k.z]);
  const vec2 cs = vec2(c[k.x] - ray.shear.x * c[k.z], c[k.y] - ray.shear.y * c[k.z]);
  const float u = cs.x * bs.y - cs.y * bs.x;  // edge v1-v2: the weight of v0
  const float v = as.x * cs.y - as.y * cs.x;  // edge v2-v0: the weight of v1
  const float w = bs.x * as.y - bs.y * as.x;  // edge v0-v1: the weight of v2
  if ((u < 0.0 || v < 0.0 || w < 0.0) && (u > 0.0 || v > 0.0 || w > 0.0)) return false;
  const float det = u + v + w;
  if (det == 0.0) return false;  // seen edge-on, or a degenerate triangle
  const float scaled = ray.shear.z * (u * a[k.z] + v * b[k.z] + w * c[k.z]);  // t x det
  if (det > 0.0 ? (scaled < 0.0 || scaled >= tMax * det) : (scaled > 0.0 || scaled <= tMax * det)) return false;
  const float inverseDet = 1.0 / det;
  t = scaled * inverseDet;
  bary = vec2(v, w) * inverseDet;
  return t < tMax;
}

// An interior node's children at `left` and `left + 1`, entered at the given distances (-1:
// missed): the one to visit next (kInvalidIndex: neither), the other pushed when it is hit too.
// Nearer first, so the closest hit found early prunes the farther subtree.
uint bvh_nearer_child(uint left, float leftT, float rightT, inout uint stack[kBvhStackSize], inout uint depth) {
  if (leftT < 0.0 && rightT < 0.0) return kInvalidIndex;
  if (rightT < 0.0) return left;
  if (leftT < 0.0) return left + 1u;
  const bool leftFirst = leftT <= rightT;
  stack[depth++] = leftFirst ? left + 1u : left;
  return leftFirst ? left : left + 1u;
}

vec3 bvh_transform(vec4 rows[3], vec4 v) { return vec3(dot(rows[0], v), dot(rows[1], v), dot(rows[2], v)); }

mat4x3 bvh_matrix(vec4 rows[3]) {
  return mat4x3(rows[0].x, rows[1].x, rows[2].x, rows[0].y, rows[1].y, rows[2].y, rows[0].z, rows[1].z, rows[2].z,
                rows[0].w, rows[1].w, rows[2].w);
}

// The instance's mesh BVH against the world-space ray; `closest` is the nearest accepted t so
// far and shrinks with every hit. On a hit, fills the record, primitive and barycentrics.
bool bvh_trace_instance(BvhInstance instance, vec3 origin, vec3 direction, bool anyHit, inout float closest,
                        inout RayHit hit) {
  // The object-space direction is not renormalised: t means the same distance in both spaces.
  const vec3 localOrigin = bvh_transform(instance.worldToObject, vec4(origin, 1.0));
  const vec3 localDirection = bvh_transform(instance.worldToObject, vec4(direction, 0.0));
  const vec3 inverseDirection = bvh_inverse_direction(localDirection);
  const BvhShearedRay sheared = bvh_sheared_ray(localOrigin, localDirection);
  bool found = false;
  uint stack[kBvhStackSize];
  uint depth = 0u;
  uint nodeIndex = instance.blasRoot;
  if (bvh_box_entry(b_blas_nodes[nodeIndex], localOrigin, inverseDirection, closest) < 0.0) return false;
  while (true) {
    const BvhNode node = b_blas_nodes[nodeIndex];
    if (node.count != 0u) {
      const uint count = node.count & ~kBvhLeaf;
      for (uint i = 0u; i < count; ++i) {
        const BvhTriangle tri = b_blas_triangles[node.first + i];
        float t;
        vec2 bary;
        if (!bvh_triangle_hit(tri, sheared, closest, t, bary)) continue;
        const uint record = instance.customIndex + (tri.geometry & ~kBvhTriangleCutout);
#if HIPR_FEATURE_CUTOUT
        if ((tri.geometry & kBvhTriangleCutout) != 0u && !cutout_hit(record, tri.primitive, bary, origin, direction))
          continue;
#endif
        closest = t;
        hit.record = record;
        hit.primitive = tri.primitive;
        hit.barycentrics = bary;
        found = true;
        if (anyHit) return true;
      }
    } else {
      const uint next = bvh_nearer_child(
          node.first, bvh_box_entry(b_blas_nodes[node.first], localOrigin, inverseDirection, closest),
          bvh_box_entry(b_blas_nodes[node.first + 1u], localOrigin, inverseDirection, closest), stack, depth);
      if (next != kInvalidIndex) {
        nodeIndex = next;
        continue;
      }
    }
    if (depth == 0u) break;
    nodeIndex = stack[--depth];
  }
  return found;
}

// The closest accepted hit within [0, tMax), or with anyHit the first one found (shadow rays).
bool bvh_trace(vec3 origin, vec3 direction, float tMax, bool anyHit, out RayHit hit) {
  hit.t = tMax;
  const vec3 inverseDirection = bvh_inverse_direction(direction);
  float closest = tMax;
  uint hitInstance = kInvalidIndex;
  uint stack[kBvhStackSize];
  uint depth = 0u;
  uint nodeIndex = 0u;
  if (bvh_box_entry(b_tlas_nodes[0], origin, inverseDirection, closest) < 0.0) return false;
  while (true) {
    const BvhNode node = b_tlas_nodes[nodeIndex];
    if (node.count != 0u) {
      const uint count = node.count & ~kBvhLeaf;
      for (uint i = 0u; i < count; ++i) {
        if (!bvh_trace_instance(b_tlas_instances[node.first + i], origin, direction, anyHit, closest, hit)) continue;
        hitInstance = node.first + i;
        if (anyHit) return true;
      }
    } else {
      const uint next = bvh_nearer_child(node.first, bvh_box_entry(b_tlas_nodes[node.first], origin, inverseDirection, closest),
                                         bvh_box_entry(b_tlas_nodes[node.first + 1u], origin, inverseDirection, closest),
                                         stack, depth);
      if (next != kInvalidIndex) {
        nodeIndex = next;
        continue;
      }
    }
    if (depth == 0u) break;
    nodeIndex = stack[--depth];
  }
  if (hitInstance == kInvalidIndex) return false;
  hit.t = closest;
  hit.objectToWorld = bvh_matrix(b_tlas_instances[hitInstance].objectToWorld);
  hit.worldToObject = bvh_matrix(b_tlas_instances[hitInstance].worldToObject);
  return true;
}

#endif
