#version 460
// Inspection pass: evaluates the material_inputs.glsl helpers at one surface point, so tests
// can check what the BSDF will receive (factor x texture channel, UV set, transform, frames).
// Reads: the scene buffers. Writes: one MaterialInputsProbe.
#extension GL_GOOGLE_include_directive : require
#include "common/traversal.glsl"
#extension GL_EXT_scalar_block_layout : require
#extension GL_EXT_shader_explicit_arithmetic_types_int64 : require

layout(local_size_x = 1) in;

#include "common/scene_bindings.glsl"
#include "shared/bindings/probe.h"
#include "common/sampling.glsl"
#include "common/textures.glsl"
#include "bsdf/bsdf.glsl"
#include "common/surface.glsl"
#include "common/material_inputs.glsl"

layout(push_constant, scalar) uniform Push { ProbePush u_probe; };
layout(scalar, binding = kProbeOutput) writeonly buffer Probe { MaterialInputsProbe b_probe; };

void main() {
  const mat4x3 identity = mat4x3(1.0);
  // Seen from the front: a ray against the triangle's winding normal.
  const uvec3 v = triangle_vertices(b_geometries[u_probe.record], u_probe.primitive);
  const vec3 front = cross(b_positions[v.y] - b_positions[v.x], b_positions[v.z] - b_positions[v.x]);
  const SurfaceHit hit = make_surface_hit(u_probe.record, u_probe.primitive, u_probe.barycentrics, identity, identity, -front);
  MaterialInputsProbe p;
  p.transmissionWeight = material_transmission_weight(hit);
  p.coatWeight = material_coat_weight(hit);
  p.coatRoughness = material_coat_roughness(hit);
  p.coatNormal = material_coat_normal(hit);
  p.fuzzColor = material_fuzz_color(hit);
  p.fuzzRoughness = material_fuzz_roughness(hit);
  p.specularWeight = material_specular_weight(hit);
  p.specularColor = material_specular_color(hit);
  p.thinFilmWeight = material_thin_film_weight(hit);
  p.thinFilmThickness = material_thin_film_thickness(hit);
  const MaterialAnisotropy a = material_anisotropy(hit);
  p.anisotropyStrength = a.strength;
  p.anisotropyDirection = a.direction;
  b_probe = p;
}
