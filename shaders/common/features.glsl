// Compile-time features of the path-tracing kernel: "skip what a scene doesn't need".
// The renderer defines each HIPR_FEATURE_* as 0 or 1 from what the scene uses
// (src/render/kernel_features.cpp, which lists the same names in the same order) and
// recompiles when an edit brings in a feature the kernel lacks. A feature left out turns what
// it would read into a constant (no coat, no texture, no emission, no light of that kind, every
// triangle opaque, ...), so the compiler drops its code instead of branching over it.
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
#ifndef HIPR_FEATURE_DISPERSION  // transmission_dispersion_scale > 0 on a thick transmissive material
#define HIPR_FEATURE_DISPERSION 1
#endif

// ---- what the scene holds besides BSDF lobes ----
#ifndef HIPR_FEATURE_TEXTURES  // a material reads a texture (any slot)
#define HIPR_FEATURE_TEXTURES 1
#endif
#ifndef HIPR_FEATURE_NORMAL_MAP  // a normal or coat normal texture (also the tangent frame it needs)
#define HIPR_FEATURE_NORMAL_MAP 1
#endif
#ifndef HIPR_FEATURE_EMISSION  // an emissive material: emission at hits and emissive-triangle light samples
#define HIPR_FEATURE_EMISSION 1
#endif
#ifndef HIPR_FEATURE_PUNCTUAL_LIGHTS  // point, spot or directional lights
#define HIPR_FEATURE_PUNCTUAL_LIGHTS 1
#endif
#ifndef HIPR_FEATURE_ENVIRONMENT  // an environment map: radiance of escaping rays, environment light samples
#define HIPR_FEATURE_ENVIRONMENT 1
#endif
#ifndef HIPR_FEATURE_CUTOUT  // a material that is not opaque (alpha MASK/BLEND, geometry_opacity < 1)
#define HIPR_FEATURE_CUTOUT 1
#endif
#ifndef HIPR_FEATURE_VOLUME  // Beer-Lambert absorption inside transmissive solids
#define HIPR_FEATURE_VOLUME 1
#endif

// Something to sample for next-event estimation: without it the light-sampling code is left out.
#define HIPR_HAS_LIGHTS \
  (HIPR_FEATURE_EMISSION != 0 || HIPR_FEATURE_PUNCTUAL_LIGHTS != 0 || HIPR_FEATURE_ENVIRONMENT != 0)

// A material's texture slot as the kernel reads it: without the feature every slot is empty
// (kInvalidIndex), which every lookup tests first, so the lookups fold away.
#define hipr_texture_slot(slot) (HIPR_FEATURE_TEXTURES != 0 ? (slot) : kInvalidIndex)
#define hipr_normal_map_slot(slot) (HIPR_FEATURE_NORMAL_MAP != 0 ? hipr_texture_slot(slot) : kInvalidIndex)

#endif
