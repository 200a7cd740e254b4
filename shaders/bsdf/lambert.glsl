// Lambertian diffuse lobe in its local frame (n = +Z). Shared with C++ (shared/glsl_cpp.h):
// tests/bsdf_test.cpp checks these very functions on the CPU.
#ifndef HIPR_LAMBERT_GLSL
#define HIPR_LAMBERT_GLSL

#include "../common/sampling.glsl"

// f * cos for unit albedo.
HIPR_FN float lambert_eval_cos(float cosTheta) { return max(cosTheta, 0.0f) * kInvPi; }

HIPR_FN float lambert_pdf(float cosTheta) { return max(cosTheta, 0.0f) * kInvPi; }

HIPR_FN vec3 lambert_sample_local(vec2 u) { return sample_cosine_hemisphere(u); }

#endif
