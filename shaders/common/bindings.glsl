// Buffers of the path-tracing kernels (set 0). Layouts come from shared/abi.h.
#ifndef HIPR_BINDINGS_GLSL
#define HIPR_BINDINGS_GLSL

#include "../shared/abi.h"

layout(binding = kBindingTlas) uniform accelerationStructureEXT u_tlas;
layout(scalar, binding = kBindingPositions) readonly buffer Positions { vec3 b_positions[]; };
layout(scalar, binding = kBindingNormals) readonly buffer Normals { vec3 b_normals[]; };
layout(scalar, binding = kBindingTangents) readonly buffer Tangents { vec4 b_tangents[]; };
layout(scalar, binding = kBindingUvs) readonly buffer Uvs { vec4 b_uvs[]; };  // uv0.xy, uv1.zw
layout(scalar, binding = kBindingIndices) readonly buffer Indices { uint b_indices[]; };
layout(scalar, binding = kBindingGeometries) readonly buffer Geometries { GeometryRecord b_geometries[]; };
layout(scalar, binding = kBindingMaterials) readonly buffer Materials { MaterialBlock b_materials[]; };
layout(scalar, binding = kBindingTextures) readonly buffer Textures { TextureInfo b_textures[]; };
layout(scalar, binding = kBindingTexels) readonly buffer Texels { uint b_texels[]; };
layout(scalar, binding = kBindingLights) readonly buffer Lights { Light b_lights[]; };
layout(scalar, binding = kBindingLightCdf) readonly buffer LightCdf { float b_light_cdf[]; };
// Environment: RGB texels (3 floats each), then the marginal CDF over rows (height + 1), then
// one conditional CDF per row (width + 1 each).
layout(scalar, binding = kBindingEnvironment) readonly buffer Environment { float b_env[]; };
layout(scalar, binding = kBindingTileList) readonly buffer TileList { uint b_tiles[]; };
layout(scalar, binding = kBindingAccumulation) buffer Accumulation { PixelAccum b_accum[]; };
layout(scalar, binding = kBindingStats) buffer Stats { RenderStats b_stats; };
layout(scalar, binding = kBindingFrame) readonly buffer Frame { FrameParams u_frame; };
layout(scalar, binding = kBindingTileFlags) buffer TileFlags { uint b_tile_flags[]; };
layout(scalar, binding = kBindingTileBackground) readonly buffer TileBackground { uint b_tile_background[]; };
layout(scalar, binding = kBindingBsdfTables) readonly buffer BsdfTables { float b_bsdf_tables[]; };

#endif
