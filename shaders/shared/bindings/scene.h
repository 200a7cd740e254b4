// Set 1 of every kernel that reads the scene or the frame parameters: GpuScene's descriptor set.
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_SCENE_H
#define HIPR_BINDINGS_SCENE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kSceneSet = 1u;
HIPR_CONST uint kSceneTlas = 0u;         // ray queries: the TLAS (software traversal: unbound)
HIPR_CONST uint kScenePositions = 1u;     // vec3 per vertex, object space
HIPR_CONST uint kSceneNormals = 2u;       // vec3 per vertex
HIPR_CONST uint kSceneTangents = 3u;      // vec4 per vertex (w = handedness)
HIPR_CONST uint kSceneUvs = 4u;           // vec4 per vertex: TEXCOORD_0 in xy, TEXCOORD_1 in zw
HIPR_CONST uint kSceneIndices = 5u;       // uint, 3 per triangle, relative to the vertex offset
HIPR_CONST uint kSceneGeometries = 6u;    // GeometryRecord per (instance, primitive)
HIPR_CONST uint kSceneMaterials = 7u;     // MaterialBlock
HIPR_CONST uint kSceneTextures = 8u;      // TextureInfo
HIPR_CONST uint kSceneTexels = 9u;        // packed RGBA8 texels of all textures
HIPR_CONST uint kSceneLights = 10u;       // Light
HIPR_CONST uint kSceneLightCdf = 11u;     // float: two CDFs of lightCount + 1 entries (light_tables.h)
HIPR_CONST uint kSceneEnvironment = 12u;  // RGB texels, then marginal and conditional CDFs (floats)
HIPR_CONST uint kSceneBsdfTables = 13u;   // float: generated BSDF tables (bsdf/ggx_energy_table.glsl)
HIPR_CONST uint kSceneFrame = 14u;        // FrameParams: camera, image and tiles, HiPR weights
// Software traversal only (devices without ray queries; shaders/common/bvh_traversal.glsl):
HIPR_CONST uint kSceneBlasNodes = 15u;      // BvhNode: every mesh's BVH, object space
HIPR_CONST uint kSceneBlasTriangles = 16u;  // BvhTriangle: their leaves' triangles
HIPR_CONST uint kSceneTlasNodes = 17u;      // BvhNode: the BVH over visible instances, world space
HIPR_CONST uint kSceneTlasInstances = 18u;  // BvhInstance: its leaves' instances
HIPR_CONST uint kSceneLightTree = 19u;      // LightTreeNode: the tree over lights, root first
// Path guiding (common/guiding.glsl), per grid cell:
HIPR_CONST uint kSceneGuideCounts = 20u;  // uint64 x kGuideSumSlots: the training's sums and largest splats per bin
HIPR_CONST uint kSceneGuide = 21u;        // float x kGuideSlots: the bins' CDF, then the guide's probability
// Ray queries only (render/traversal_order.h):
HIPR_CONST uint kSceneTriangleOrder = 22u;  // uint per triangle as built: its index in its primitive

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
