// The display's tone mappers: exposed linear Rec. 709 radiance -> linear display values in
// [0, 1], which srgb.glsl then encodes. Shared with C++ (shared/glsl_cpp.h): image/tonemap.cpp
// runs these very functions for PNG output and FLIP, so the window, the files and the metric
// agree. Each follows its published definition (tests/tonemap_test.cpp checks hand-evaluated
// values):
//   clamp:       min(max(c, 0), 1), the project's original display (regression images exact).
//   pbr-neutral: Khronos PBR Neutral (KhronosGroup/ToneMapping, PBR_Neutral/README.md): base
//                colours shown as authored up to 0.76, highlights compressed towards white.
//   agx:         Troy Sobotka's AgX base look as fitted by Wrensch (iolite engine, "Minimal AgX
//                implementation", 2023): inset matrix, log2 encoding over [-12.47393, 4.026069]
//                EV, the 6th-order fit of the default contrast curve, outset matrix; its output is
//                display-encoded for a 2.2 gamma, linearized here with pow(x, 2.2).
//   aces:        Stephen Hill's fit of the ACES RRT + sRGB ODT (BakingLab's ACES.hlsl): input
//                matrix, rational fit, output matrix, clamped.
#ifndef HIPR_TONE_MAPPERS_GLSL
#define HIPR_TONE_MAPPERS_GLSL

#include "../shared/glsl_cpp.h"

// The order is the CLI's and the viewer's (image/tonemap.h's ToneMapper).
const uint kToneClamp = 0u;
const uint kTonePbrNeutral = 1u;
const uint kToneAgx = 2u;
const uint kToneAces = 3u;

HIPR_FN vec3 tone_pbr_neutral(vec3 c) {
  const float f90 = 0.04f;
  const float start = 0.8f - f90;  // K_s: compression starts here
  const float desaturation = 0.15f;  // K_d
  const float x = min(c.x, min(c.y, c.z));
  const float offset = x < 2.0f * f90 ? x - x * x / (4.0f * f90) : f90;
  c -= vec3(offset);
  const float peak = max(c.x, max(c.y, c.z));
  if (peak < start) return c;
  const float d = 1.0f - start;
  const float new_peak = 1.0f - d * d / (peak + d - start);
  c *= new_peak / peak;
  const float g = 1.0f - 1.0f / (desaturation * (peak - new_peak) + 1.0f);
  return mix(c, vec3(new_peak), g);
}

HIPR_FN vec3 agx_contrast(vec3 x) {
  const vec3 x2 = x * x;
  const vec3 x4 = x2 * x2;
  return 15.5f * x4 * x2 - 40.14f * x4 * x + 31.96f * x4 - 6.868f * x2 * x + 0.4298f * x2 +
         0.1191f * x - vec3(0.00232f);
}

HIPR_FN vec3 tone_agx(vec3 c) {
  // Column-major, as GLSL and glm both read a mat3's constructor.
  const mat3 inset = mat3(0.842479062253094f, 0.0423282422610123f, 0.0423756549057051f,
                          0.0784335999999992f, 0.878468636469772f, 0.0784336f,
                          0.0792237451477643f, 0.0791661274605434f, 0.879142973793104f);
  const mat3 outset = mat3(1.19687900512017f, -0.0528968517574562f, -0.0529716355144438f,
                           -0.0980208811401368f, 1.15190312990417f, -0.0980434501171241f,
                           -0.0990297440797205f, -0.0989611768448433f, 1.15107367264116f);
  const float min_ev = -12.47393f;
  const float max_ev = 4.026069f;
  // log2(0) is -inf: the floor keeps black at the bottom of the encoding, not NaN.
  vec3 v = max(inset * c, vec3(1e-10f));
  v = clamp(log2(v), vec3(min_ev), vec3(max_ev));
  v = (v - vec3(min_ev)) / (max_ev - min_ev);
  v = outset * agx_contrast(v);
  return pow(clamp(v, vec3(0.0f), vec3(1.0f)), vec3(2.2f));
}

HIPR_FN vec3 aces_rrt_odt_fit(vec3 v) {
  const vec3 a = v * (v + vec3(0.0245786f)) - vec3(0.000090537f);
  const vec3 b = v * (0.983729f * v + vec3(0.4329510f)) + vec3(0.238081f);
  return a / b;
}

HIPR_FN vec3 tone_aces(vec3 c) {
  // BakingLab writes these row by row; transposed here for the column-major constructor.
  const mat3 input_mat = mat3(0.59719f, 0.07600f, 0.02840f,   // column 0
                              0.35458f, 0.90834f, 0.13383f,   // column 1
                              0.04823f, 0.01566f, 0.83777f);  // column 2
  const mat3 output_mat = mat3(1.60475f, -0.10208f, -0.00327f,  //
                               -0.53108f, 1.10813f, -0.07276f,  //
                               -0.07367f, -0.00605f, 1.07602f);
  return clamp(output_mat * aces_rrt_odt_fit(input_mat * c), vec3(0.0f), vec3(1.0f));
}

// Exposed radiance -> linear display values in [0, 1]. Non-finite and negative channels are
// taken as 0 first, as srgb_encode takes them, and values past half-float range as that range
// (every mapper is white there; ACES' rational fit would divide infinity by infinity).
HIPR_FN vec3 tone_map(vec3 c, uint mapper) {
  const float kBrightest = 65504.0f;
  c = vec3(isnan(c.x) || isinf(c.x) ? 0.0f : clamp(c.x, 0.0f, kBrightest),
           isnan(c.y) || isinf(c.y) ? 0.0f : clamp(c.y, 0.0f, kBrightest),
           isnan(c.z) || isinf(c.z) ? 0.0f : clamp(c.z, 0.0f, kBrightest));
  if (mapper == kTonePbrNeutral) c = tone_pbr_neutral(c);
  if (mapper == kToneAgx) c = tone_agx(c);
  if (mapper == kToneAces) c = tone_aces(c);
  return clamp(c, vec3(0.0f), vec3(1.0f));
}

#endif
