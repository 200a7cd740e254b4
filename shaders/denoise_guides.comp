#version 460
// The display denoiser's guides: one ray through every pixel centre (the ray of visibility.comp)
// records the surface it hits, how far, its shading normal facing the camera, the albedo the
// radiance is demodulated by and the radiance the surface emits toward the camera. Run when the scene or the camera changed.
// Reads: TLAS (or the software BVH), FrameParams, geometry, materials and textures.
// Writes: DenoiseGuide per pixel.
#extension GL_GOOGLE_include_directive : require
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 64) in;

#include "common/scene_bindings.glsl"
#include "common/denoise.glsl"
#include "common/dispatch.glsl"
#include "common/pixel_ray.glsl"
#include "common/sampling.glsl"
#include "common/textures.glsl"
#include "bsdf/bsdf.glsl"
#include "common/surface.glsl"
#include "common/material_inputs.glsl"
#include "common/cutout.glsl"
#include "common/scene_trace.glsl"

layout(scalar, binding = kDenoiseGuides) writeonly buffer Guides { DenoiseGuide b_guides[]; };

// The share of light a surface reflects or passes on, as a colour: the base colour for
// diffuse and metal alike (glTF's metal tints its reflection by it), white where light goes
// through (glass shows what lies behind it, not its own colour).
vec3 surface_albedo(SurfaceHit hit) {
  const uint material = hit.material;
  const vec3 base = material_color(b_materials[material].base_color, b_materials[material].base_color_texture, hit) *
                    b_materials[material].base_weight;
  const float transmission = HIPR_FEATURE_TRANSMISSION != 0 ? clamp(material_transmission_weight(hit), 0.0, 1.0) : 0.0;
  return clamp(mix(base, vec3(1.0), transmission), 0.0, 1.0);
}

void main() {
  const uint index = dispatch_index();
  if (index >= u_frame.width * u_frame.height) return;
  const uvec2 pixel = uvec2(index % u_frame.width, index / u_frame.width);
  const vec3 direction = pixel_centre_ray(pixel);
  DenoiseGuide guide = DenoiseGuide(kInvalidIndex, 0.0, 0u, packUnorm4x8(vec4(1.0)), 0u, 0u);
  RayHit hit;
  if (trace_closest(u_frame.cameraPosition, direction, 3.0e38, hit)) {
    const SurfaceHit surface =
        make_surface_hit(hit.record, hit.primitive, hit.barycentrics, hit.objectToWorld, hit.worldToObject, direction);
    guide.record = hit.record;
    guide.distance = hit.t;
    guide.normal = pack_normal(surface.shadingNormal);
    guide.albedo = packUnorm4x8(vec4(surface_albedo(surface), 1.0));
    // As the camera path adds it at its first hit (trace_tiles.comp: shading_params).
    const bool emits = surface.frontFacing || (b_materials[surface.material].flags & kMaterialDoubleSided) != 0u;
    const vec3 emission =
        emits ? material_emission(surface.material, surface.uvs, dot(surface.geometricNormal, -direction)) : vec3(0.0);
    guide.emissionRG = packHalf2x16(emission.rg);
    guide.emissionB = packHalf2x16(vec2(emission.b, 0.0));
  }
  b_guides[index] = guide;
}
