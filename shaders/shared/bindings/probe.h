// Set 0 of material_probe.comp (MaterialProbe, for inspection).
// Compiles as C++ (namespace hipr::abi) and as GLSL, like ../abi.h: the one declaration of these
// binding numbers, named by the kernel's GLSL layouts and by its C++ pass.
#ifndef HIPR_BINDINGS_PROBE_H
#define HIPR_BINDINGS_PROBE_H

#include "../abi.h"

#ifdef __cplusplus
namespace hipr::abi {
#endif

HIPR_CONST uint kProbeOutput = 0u;  // MaterialInputsProbe (one)

#ifdef __cplusplus
}  // namespace hipr::abi
#endif
#endif
