// Lets a GLSL-style header compile as C++ too, so CPU tests run the very code the GPU runs.
// Rules for shared code: float literals carry an `f`, out/inout parameters use OUT()/INOUT(),
// functions are marked HIPR_FN, and only functions GLSL and glm both have are called.
#ifndef HIPR_GLSL_CPP_H
#define HIPR_GLSL_CPP_H

// A constant table of uints: HIPR_UINT_TABLE(name, size) values... HIPR_TABLE_END.
#ifdef __cplusplus
#include <glm/glm.hpp>
#define HIPR_FN inline
#define OUT(T) T&
#define INOUT(T) T&
#define HIPR_UINT_TABLE(name, size) inline constexpr glm::uint name[size] = {
#define HIPR_TABLE_END };
#else
#define HIPR_FN
#define OUT(T) out T
#define INOUT(T) inout T
#define HIPR_UINT_TABLE(name, size) const uint name[size] = uint[size](
#define HIPR_TABLE_END );
#endif

#endif
