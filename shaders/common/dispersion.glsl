// Dispersion (OpenPBR's transmission_dispersion_*, glTF's KHR_materials_dispersion) in an RGB
// renderer. A path that meets a dispersive dielectric picks one of the three colour channels,
// each with probability 1/3; its throughput keeps that channel alone, times 3, and from then on
// every dispersive interface refracts it with that channel's index. The expected image is
// exactly that of a spectral renderer that samples three wavelengths, one per channel; the price
// is colour noise on the paths through dispersive glass, and only there. Shared with C++ (see
// shared/glsl_cpp.h): tests check the very code the kernels run.
#ifndef HIPR_DISPERSION_GLSL
#define HIPR_DISPERSION_GLSL

#include "../shared/abi.h"
#include "../shared/glsl_cpp.h"

// The wavelength (nm) a channel stands for: the dominant wavelengths of the sRGB primaries.
HIPR_FN float dispersion_wavelength(uint channel) {
  return channel == 0u ? 611.3f : (channel == 1u ? 549.1f : 464.3f);
}

// The index at `wavelength` (nm) of a dielectric whose index is `ior` at the helium d line
// (587.56 nm) and whose Abbe number is 1 / inverseAbbe: the two-term Cauchy fit through
// n_F - n_C = (n_d - 1) / V, as KHR_materials_dispersion gives it (523655 = the inverse of
// 1/486.13^2 - 1/656.27^2, 1.5168 = 523655 / 587.56^2). inverseAbbe 0: no dispersion, `ior`
// exactly.
HIPR_FN float dispersed_ior(float ior, float inverseAbbe, float wavelength) {
  return max(ior + (ior - 1.0f) * inverseAbbe * (523655.0f / (wavelength * wavelength) - 1.5168f), 1.0f);
}

// The channel a uniform number in [0,1) picks.
HIPR_FN uint dispersion_channel(float u) { return min(uint(u * 3.0f), 2u); }

// What the path's throughput is multiplied by when it takes `channel`: that channel over its
// probability, the others 0.
HIPR_FN vec3 dispersion_channel_weight(uint channel) {
  return vec3(channel == 0u ? 3.0f : 0.0f, channel == 1u ? 3.0f : 0.0f, channel == 2u ? 3.0f : 0.0f);
}

#endif
