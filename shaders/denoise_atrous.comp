#version 460
// One pass of the display denoiser's edge-avoiding a-trous filter (Dammertz et al. 2010, with
// SVGF's variance-guided luminance edge, Schied et al. 2017): a 5 x 5 B3-spline kernel whose taps
// lie `step` pixels apart, each weighed by how alike the two pixels are:
//   key       mixing (keys_mix), or no weight (same surface, same scene state: denoise_prepare.comp)
//   colour    exp(-L(|c_p - c_q|) / (4 strength sqrt(Var_p))), L the luminance of the channels'
//             differences, Var_p the variance of the pixel's luminance blurred
//             over its 3 x 3 neighbours (blurred_variance): a precise pixel takes nothing from
//             neighbours that differ
//   normal    max(0, n_p . n_q)^32
//   plane     exp(-|n_p . (x_q - x_p)| / (0.05 |x_q - x_p|)): q lies in p's tangent plane
// and the variance is carried through as Var' = sum w^2 Var / (sum w)^2. Passes double the step
// (1, 2, 4, 8, 16): a 125-pixel footprint for 25 taps a pass.
// Reads: the guides (the pixel's own; its neighbours' normals and distances packed), keys,
// samples, the pass's input, FrameParams (the pixel rays). Writes: the
// pass's output (denoise_blend.comp takes the last one).
#extension GL_GOOGLE_include_directive : require
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/frame.glsl"
#include "common/denoise.glsl"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"

layout(scalar, binding = kDenoiseGuides) readonly buffer Guides { DenoiseGuide b_guides[]; };
layout(scalar, binding = kDenoiseKeys) readonly buffer Keys { uint b_keys[]; };
layout(scalar, binding = kDenoiseInput) readonly buffer Input { vec4 b_input[]; };
layout(scalar, binding = kDenoiseOutput) writeonly buffer Output { vec4 b_output[]; };
layout(scalar, binding = kDenoiseSamples) readonly buffer Samples { uint b_samples[]; };
layout(scalar, binding = kDenoiseGeometry) readonly buffer Geometry { uvec2 b_geometry[]; };  // normal, distance
layout(push_constant, scalar) uniform Push { DenoisePush u_push; };

const float kSpline[3] = float[3](3.0 / 8.0, 1.0 / 4.0, 1.0 / 16.0);
const float kNormalPower = 32.0;
const float kPlaneTolerance = 0.05;

bool inside(ivec2 q) { return q.x >= 0 && q.y >= 0 && q.x < int(u_push.width) && q.y < int(u_push.height); }
uint pixel_index(ivec2 q) { return uint(q.y) * u_push.width + uint(q.x); }

vec3 guide_position(uvec2 pixel, float distance) {
  return u_frame.cameraPosition + pixel_centre_ray(pixel) * distance;
}

// The pixel's variance blurred over its 3 x 3 neighbours whose keys mix (weights 1/4, 1/2, 1/4
// per axis): a variance from a few samples is itself noisy. What is blurred is the noise of the
// light (a neighbour's variance times its samples), over the pixel's own samples: a pixel with
// a million samples among noisy 4-sample ones stays precise.
float blurred_variance(ivec2 p, uint key) {
  const float own = float(b_samples[pixel_index(p)]);
  float sum = 0.0, weights = 0.0;
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx) {
      const ivec2 q = p + ivec2(dx, dy);
      if (!inside(q) || !keys_mix(b_keys[pixel_index(q)], key)) continue;
      const float w = (dx == 0 ? 0.5 : 0.25) * (dy == 0 ? 0.5 : 0.25);
      sum += w * b_input[pixel_index(q)].w * float(b_samples[pixel_index(q)]) / own;
      weights += w;
    }
  return sum / weights;
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_push.width * u_push.height) return;
  const ivec2 p = ivec2(index % u_push.width, index / u_push.width);
  const uint key = b_keys[index];
  const vec4 centre = b_input[index];
  if (key == kDenoiseKept) {
    b_output[index] = centre;
    return;
  }
  const DenoiseGuide guide = b_guides[index];
  const bool surface = guide.record != kInvalidIndex;
  const vec3 normal = surface ? unpack_normal(guide.normal) : vec3(0.0);
  const vec3 position = surface ? guide_position(uvec2(p), guide.distance) : vec3(0.0);
  const float tolerance = 4.0 * u_push.strength * sqrt(blurred_variance(p, key));
  const int step = int(u_push.step);

  vec3 sum = vec3(0.0);
  float weights = 0.0, variance = 0.0;
  for (int dy = -2; dy <= 2; ++dy)
    for (int dx = -2; dx <= 2; ++dx) {
      const ivec2 q = p + step * ivec2(dx, dy);
      if (!inside(q)) continue;
      const uint neighbour = pixel_index(q);
      if (!keys_mix(b_keys[neighbour], key)) continue;
      const vec4 value = b_input[neighbour];
      float w = kSpline[abs(dx)] * kSpline[abs(dy)];
      if (neighbour != index) {
        // Each channel's difference counts: two values of one luminance may differ in colour.
        const float difference = denoise_luminance(abs(value.rgb - centre.rgb));
        w *= tolerance > 0.0 ? exp(-difference / tolerance) : 0.0;
        if (surface) {
          const uvec2 other = b_geometry[neighbour];
          w *= pow(max(dot(normal, unpack_normal(other.x)), 0.0), kNormalPower);
          const vec3 offset = guide_position(uvec2(q), uintBitsToFloat(other.y)) - position;
          const float span = length(offset);
          if (span > 0.0) w *= exp(-abs(dot(normal, offset)) / (kPlaneTolerance * span));
        }
      }
      sum += w * value.rgb;
      weights += w;
      variance += w * w * value.w;
    }
  // The centre's own weight (kSpline[0]^2) keeps `weights` positive.
  const vec4 filtered = vec4(sum / weights, variance / (weights * weights));
  b_output[index] = filtered;
}
