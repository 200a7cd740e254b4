// image/tonemap.cpp's display encoding, for the kernels that make window pixels (display.comp,
// overlay.comp): the same sRGB curve and 8-bit rounding, so the window shows what PNG output and
// the CPU's debug images hold.
#ifndef HIPR_SRGB_GLSL
#define HIPR_SRGB_GLSL

// srgb_encode: non-finite -> 0, clamp to [0, 1], sRGB transfer curve.
float srgb_encode(float x) {
  x = (isnan(x) || isinf(x)) ? 0.0 : clamp(x, 0.0, 1.0);
  return x <= 0.0031308 ? 12.92 * x : 1.055 * pow(x, 1.0 / 2.4) - 0.055;
}

// A value in [0, 1] as its nearest byte.
uint srgb_byte(float encoded) { return uint(floor(clamp(encoded, 0.0, 1.0) * 255.0 + 0.5)); }

uvec3 srgb_bytes(vec3 linear) {
  return uvec3(srgb_byte(srgb_encode(linear.r)), srgb_byte(srgb_encode(linear.g)), srgb_byte(srgb_encode(linear.b)));
}

#endif
