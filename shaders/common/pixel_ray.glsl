// The ray through a pixel's centre, as stage 1 casts it (visibility.comp) and as the kernels
// that find a pixel's surface again cast it (light_reach.comp, reproject_display.comp): one
// expression, so they all see the same surface. And a camera sample's ray (trace_tiles.comp;
// the denoiser's guides look at the pixel's footprint with it). Needs frame.glsl (u_frame).
#ifndef HIPR_PIXEL_RAY_GLSL
#define HIPR_PIXEL_RAY_GLSL

vec3 pixel_centre_ray(uvec2 pixel) {
  const vec2 ndc = (vec2(pixel) + 0.5) / vec2(u_frame.width, u_frame.height) * 2.0 - 1.0;
  return normalize(u_frame.cameraForward + ndc.x * u_frame.tanHalfFovY * u_frame.aspect * u_frame.cameraRight -
                   ndc.y * u_frame.tanHalfFovY * u_frame.cameraUp);
}

// A camera sample's ray: through `jitter` in [0, 1)^2 of the pixel (a box filter over the pixel).
vec3 camera_ray_direction(uvec2 pixel, vec2 jitter) {
  const vec2 ndc = (vec2(pixel) + jitter) / vec2(u_frame.width, u_frame.height) * 2.0 - 1.0;
  const float x = ndc.x * u_frame.tanHalfFovY * u_frame.aspect;
  const float y = -ndc.y * u_frame.tanHalfFovY;  // image rows go down, camera +Y goes up
  return normalize(u_frame.cameraForward + x * u_frame.cameraRight + y * u_frame.cameraUp);
}

#endif
