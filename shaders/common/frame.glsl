// The frame parameters (camera, image and tiles, HiPR weights), from the scene's set: kernels
// that read nothing else of the scene include only this.
#ifndef HIPR_FRAME_GLSL
#define HIPR_FRAME_GLSL

#include "../shared/bindings/scene.h"

layout(scalar, set = kSceneSet, binding = kSceneFrame) readonly buffer Frame { FrameParams u_frame; };

#endif
