// Every ray the kernels trace goes through these two functions: the closest hit, and whether
// anything blocks a segment. Both run the opacity cutout on candidate triangles of geometry
// that is not opaque, and both trace through ray queries or, on devices without them, hipr's
// own BVH (traversal.glsl says which). Rays start at t = 0.
// Needs scene_bindings.glsl, textures.glsl and cutout.glsl.
#ifndef HIPR_SCENE_TRACE_GLSL
#define HIPR_SCENE_TRACE_GLSL

struct RayHit {
  float t;
  uint record;  // GeometryRecord: the instance's first record + the primitive of its mesh
  uint primitive;
  vec2 barycentrics;  // of vertices 1 and 2
  mat4x3 objectToWorld;
  mat4x3 worldToObject;
};

#if HIPR_SOFTWARE_TRAVERSAL

#include "bvh_traversal.glsl"

bool trace_closest(vec3 origin, vec3 direction, float tMax, out RayHit hit) {
  return bvh_trace(origin, direction, tMax, false, hit);
}

bool trace_occluded(vec3 origin, vec3 direction, float tMax) {
  RayHit hit;
  return bvh_trace(origin, direction, tMax, true, hit);
}

#else

// Geometry whose material needs no test is VK_GEOMETRY_OPAQUE_BIT_KHR and never reaches the
// candidate loop; without cutout geometry in the scene every ray is opaque.
const uint kCutoutRayFlags = HIPR_FEATURE_CUTOUT != 0 ? gl_RayFlagsNoneEXT : gl_RayFlagsOpaqueEXT;

// The BLASes hold each primitive's triangles in spatial order (render/traversal_order.h): the
// index a query reports, mapped back to the triangle's own.
uint built_triangle(uint record, uint built) {
  return b_triangle_order[b_geometries[record].firstIndex / 3u + built];
}

// Runs an initialised query to its end, confirming the candidate triangles that pass the test.
void cutout_proceed(rayQueryEXT query, vec3 origin, vec3 direction) {
#if HIPR_FEATURE_CUTOUT == 0
  // Only opaque triangles: the first call runs the traversal to its end (and returns false).
  rayQueryProceedEXT(query);
#else
  while (rayQueryProceedEXT(query)) {
    if (rayQueryGetIntersectionTypeEXT(query, false) != gl_RayQueryCandidateIntersectionTriangleEXT) continue;
    const uint record = uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, false)) +
                        uint(rayQueryGetIntersectionGeometryIndexEXT(query, false));
    if (cutout_hit(record, built_triangle(record, uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, false))),
                   rayQueryGetIntersectionBarycentricsEXT(query, false), origin, direction))
      rayQueryConfirmIntersectionEXT(query);
  }
#endif
}

bool trace_closest(vec3 origin, vec3 direction, float tMax, out RayHit hit) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, u_tlas, kCutoutRayFlags, 0xff, origin, 0.0, direction, tMax);
  cutout_proceed(query, origin, direction);
  if (rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionTriangleEXT) return false;
  hit.t = rayQueryGetIntersectionTEXT(query, true);
  hit.record = uint(rayQueryGetIntersectionInstanceCustomIndexEXT(query, true)) +
               uint(rayQueryGetIntersectionGeometryIndexEXT(query, true));
  hit.primitive = built_triangle(hit.record, uint(rayQueryGetIntersectionPrimitiveIndexEXT(query, true)));
  hit.barycentrics = rayQueryGetIntersectionBarycentricsEXT(query, true);
  hit.objectToWorld = rayQueryGetIntersectionObjectToWorldEXT(query, true);
  hit.worldToObject = rayQueryGetIntersectionWorldToObjectEXT(query, true);
  return true;
}

bool trace_occluded(vec3 origin, vec3 direction, float tMax) {
  rayQueryEXT query;
  rayQueryInitializeEXT(query, u_tlas, gl_RayFlagsTerminateOnFirstHitEXT | kCutoutRayFlags, 0xff, origin, 0.0,
                        direction, tMax);
  cutout_proceed(query, origin, direction);
  return rayQueryGetIntersectionTypeEXT(query, true) != gl_RayQueryCommittedIntersectionNoneEXT;
}

#endif
#endif
