// The scene as every tracing kernel reads it: set 1, GpuScene's descriptor set (numbers in
// shared/bindings/scene.h; struct layouts in shared/abi.h).
#ifndef HIPR_SCENE_BINDINGS_GLSL
#define HIPR_SCENE_BINDINGS_GLSL

#include "traversal.glsl"
#include "../shared/bindings/scene.h"
#include "frame.glsl"

#if HIPR_SOFTWARE_TRAVERSAL
layout(scalar, set = kSceneSet, binding = kSceneBlasNodes) readonly buffer BlasNodes { BvhNode b_blas_nodes[]; };
layout(scalar, set = kSceneSet, binding = kSceneBlasTriangles) readonly buffer BlasTriangles { BvhTriangle b_blas_triangles[]; };
layout(scalar, set = kSceneSet, binding = kSceneTlasNodes) readonly buffer TlasNodes { BvhNode b_tlas_nodes[]; };
layout(scalar, set = kSceneSet, binding = kSceneTlasInstances) readonly buffer TlasInstances { BvhInstance b_tlas_instances[]; };
#else
layout(set = kSceneSet, binding = kSceneTlas) uniform accelerationStructureEXT u_tlas;
layout(scalar, set = kSceneSet, binding = kSceneTriangleOrder) readonly buffer TriangleOrder { uint b_triangle_order[]; };
#endif
layout(scalar, set = kSceneSet, binding = kScenePositions) readonly buffer Positions { vec3 b_positions[]; };
layout(scalar, set = kSceneSet, binding = kSceneNormals) readonly buffer Normals { vec3 b_normals[]; };
layout(scalar, set = kSceneSet, binding = kSceneTangents) readonly buffer Tangents { vec4 b_tangents[]; };
layout(scalar, set = kSceneSet, binding = kSceneUvs) readonly buffer Uvs { vec4 b_uvs[]; };  // uv0.xy, uv1.zw
layout(scalar, set = kSceneSet, binding = kSceneIndices) readonly buffer Indices { uint b_indices[]; };
layout(scalar, set = kSceneSet, binding = kSceneGeometries) readonly buffer Geometries { GeometryRecord b_geometries[]; };
layout(scalar, set = kSceneSet, binding = kSceneMaterials) readonly buffer Materials { MaterialBlock b_materials[]; };
layout(scalar, set = kSceneSet, binding = kSceneTextures) readonly buffer Textures { TextureInfo b_textures[]; };
layout(scalar, set = kSceneSet, binding = kSceneTexels) readonly buffer Texels { uint b_texels[]; };
layout(scalar, set = kSceneSet, binding = kSceneLights) readonly buffer Lights { Light b_lights[]; };
layout(scalar, set = kSceneSet, binding = kSceneLightCdf) readonly buffer LightCdf { float b_light_cdf[]; };
layout(scalar, set = kSceneSet, binding = kSceneLightTree) readonly buffer LightTree { LightTreeNode b_light_tree[]; };
// Environment: RGB texels (3 floats each), then the marginal CDF over rows (height + 1), then
// one conditional CDF per row (width + 1 each).
layout(scalar, set = kSceneSet, binding = kSceneEnvironment) readonly buffer Environment { float b_env[]; };
layout(scalar, set = kSceneSet, binding = kSceneBsdfTables) readonly buffer BsdfTables { float b_bsdf_tables[]; };

#endif
