// Lambertian diffuse lobe in its local frame (n = +Z). Plain functions of scalars and vectors,
// so the same text compiles as GLSL and as C++ (through glm) for CPU tests.
#ifndef HIPR_LAMBERT_GLSL
#define HIPR_LAMBERT_GLSL

// f * cos for unit albedo.
float lambert_eval_cos(float cosTheta) { return max(cosTheta, 0.0f) * 0.31830988618379f; }

float lambert_pdf(float cosTheta) { return max(cosTheta, 0.0f) * 0.31830988618379f; }

vec3 lambert_sample_local(vec2 u) { return sample_cosine_hemisphere(u); }

#endif
