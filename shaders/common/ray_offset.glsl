// Robust ray origins: move a hit point off its surface by a few ULPs along the geometric
// normal, scaled with the position's magnitude (method of Waechter & Binder, "A Fast and Robust
// Method for Avoiding Self-Intersection", RT Gems 2019). Near zero, where ULPs vanish, their
// fixed offset suits a scene about a unit across; here it follows the scene's size
// (FrameParams::rayOffsetScale), so a scene a ten-thousandth of a unit across gets the offsets
// a unit-sized one gets, relative to its size. (A fixed 1/65536 started the rays of a scene
// 1e-4 across 15% of its size away from their surfaces.)
// Needs frame.glsl (u_frame).
#ifndef HIPR_RAY_OFFSET_GLSL
#define HIPR_RAY_OFFSET_GLSL

vec3 offset_ray_origin(vec3 p, vec3 ng) {
  const float kOrigin = u_frame.rayOffsetScale * (1.0 / 32.0);
  const float kFloatScale = u_frame.rayOffsetScale * (1.0 / 65536.0);
  const float kIntScale = 256.0;
  const ivec3 of_i = ivec3(kIntScale * ng);
  const vec3 p_i = vec3(intBitsToFloat(floatBitsToInt(p.x) + (p.x < 0.0 ? -of_i.x : of_i.x)),
                        intBitsToFloat(floatBitsToInt(p.y) + (p.y < 0.0 ? -of_i.y : of_i.y)),
                        intBitsToFloat(floatBitsToInt(p.z) + (p.z < 0.0 ? -of_i.z : of_i.z)));
  return vec3(abs(p.x) < kOrigin ? p.x + kFloatScale * ng.x : p_i.x,
              abs(p.y) < kOrigin ? p.y + kFloatScale * ng.y : p_i.y,
              abs(p.z) < kOrigin ? p.z + kFloatScale * ng.z : p_i.z);
}

#endif
