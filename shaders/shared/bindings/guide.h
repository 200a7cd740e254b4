// Set 0 of guide_build.comp: GuidePass (render/guide_pass.h). Compiles as C++ (namespace
// hipr::abi) and as GLSL, like ../abi.h.
#ifndef HIPR_BINDINGS_GUIDE_H
#define HIPR_BINDINGS_GUIDE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kGuideBuildCounts = 0u;  // uint64 per cell and slot: the training's sums (scene set's kSceneGuideCounts)
HIPR_CONST uint kGuideBuildGuide = 1u;   // float per cell and slot: the guide made of them (kSceneGuide)

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
