// Compile-time material features of the path-tracing kernel: "skip what a scene doesn't need".
// The renderer defines each HIPR_FEATURE_* as 0 or 1 from what the scene's materials use
// (src/render/material_features.cpp, which lists the same names) and recompiles when an edit
// brings in a feature the kernel lacks. A feature left out makes shading_params() hand the
// BSDF a constant (no coat, no transmission, ...), so the compiler drops that lobe's code.
// Undefined means 1: the uber kernel, which the C++ tests and --uber-kernel use.
#ifndef HIPR_FEATURES_GLSL
#define HIPR_FEATURES_GLSL

#ifndef HIPR_FEATURE_SPECULAR  // dielectric specular reflection (specular_weight > 0, not fully metal)
#define HIPR_FEATURE_SPECULAR 1
#endif
#ifndef HIPR_FEATURE_METAL  // base_metalness > 0
#define HIPR_FEATURE_METAL 1
#endif
#ifndef HIPR_FEATURE_TRANSMISSION  // transmission_weight > 0
#define HIPR_FEATURE_TRANSMISSION 1
#endif
#ifndef HIPR_FEATURE_SUBSURFACE  // subsurface_weight > 0
#define HIPR_FEATURE_SUBSURFACE 1
#endif
#ifndef HIPR_FEATURE_COAT  // coat_weight > 0
#define HIPR_FEATURE_COAT 1
#endif
#ifndef HIPR_FEATURE_FUZZ  // fuzz_weight > 0
#define HIPR_FEATURE_FUZZ 1
#endif
#ifndef HIPR_FEATURE_THIN_FILM  // thin_film_weight > 0
#define HIPR_FEATURE_THIN_FILM 1
#endif
#ifndef HIPR_FEATURE_DIFFUSE_ROUGHNESS  // base_diffuse_roughness > 0 (EON instead of Lambert)
#define HIPR_FEATURE_DIFFUSE_ROUGHNESS 1
#endif
#ifndef HIPR_FEATURE_ANISOTROPY  // specular_roughness_anisotropy > 0
#define HIPR_FEATURE_ANISOTROPY 1
#endif

#endif
