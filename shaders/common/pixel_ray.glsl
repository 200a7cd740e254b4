// The ray through a pixel's centre, as stage 1 casts it (visibility.comp) and as the kernels
// that find a pixel's surface again cast it (light_reach.comp, reproject_display.comp): one
// expression, so they all see the same surface. Needs frame.glsl (u_frame).
#ifndef HIPR_PIXEL_RAY_GLSL
#define HIPR_PIXEL_RAY_GLSL

vec3 pixel_centre_ray(uvec2 pixel) {
  const vec2 ndc = (vec2(pixel) + 0.5) / vec2(u_frame.width, u_frame.height) * 2.0 - 1.0;
  return normalize(u_frame.cameraForward + ndc.x * u_frame.tanHalfFovY * u_frame.aspect * u_frame.cameraRight -
                   ndc.y * u_frame.tanHalfFovY * u_frame.cameraUp);
}

#endif
