// The frame parameters (camera, image and tiles, HiPR weights), from the scene's set: kernels
// that read nothing else of the scene include only this.
#ifndef HIPR_FRAME_GLSL
#define HIPR_FRAME_GLSL

#include "../shared/bindings/scene.h"

layout(scalar, set = kSceneSet, binding = kSceneFrame) readonly buffer Frame { FrameParams u_frame; };

// The tile a pixel belongs to (TileState::tile_of on the host).
uint tile_of_pixel(uvec2 pixel) { return (pixel.y / u_frame.tileSize) * u_frame.tilesX + pixel.x / u_frame.tileSize; }

// A tile's first pixel.
uvec2 tile_origin(uint tile) { return uvec2(tile % u_frame.tilesX, tile / u_frame.tilesX) * u_frame.tileSize; }

#endif
