// Lets a GLSL-style header compile as C++ too, so CPU tests run the very code the GPU runs.
// Rules for shared code: float literals carry an `f`, out/inout parameters use OUT()/INOUT(),
// functions are marked HIPR_FN, and only functions GLSL and glm both have are called.
#ifndef HIPR_GLSL_CPP_H
#define HIPR_GLSL_CPP_H

#ifdef __cplusplus
#include <glm/glm.hpp>
#define HIPR_FN inline
#define OUT(T) T&
#define INOUT(T) T&
#else
#define HIPR_FN
#define OUT(T) out T
#define INOUT(T) inout T
#endif

#endif
