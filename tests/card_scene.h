#pragma once
// Scenes of square cards built in code, for tests that need to know exactly what each pixel
// sees: a camera at z = 3 looking down -Z whose view is exactly the card [-1,1]^2 at z = 0.
#include "hipr/scene.h"

namespace hipr::test {

// An empty scene with that camera; a uniform environment of radiance `env` unless 0.
Scene make_card_camera_scene(float env);

// Adds a card [-1,1]^2 facing +Z, moved by `transform`, with its own material. UVs are
// image-like: uv0 = ((x + 1) / 2, (1 - y) / 2), so pixel rows follow texture rows; uv1 mirrors
// u (uv1 = (1 - u0, v0)). Returns the material's index.
uint32_t add_card(Scene& scene, const std::string& name, const glm::mat4& transform,
                  const MaterialParameters& material);

// A material that reflects nothing and emits nothing: a card of it is black where it is hit.
MaterialParameters black_material();

// A material that reflects nothing and emits texture `texture` (1 nit per unit): a card of it
// shows the texture's texels as they are.
MaterialParameters emissive_texture_material(uint32_t texture);

}  // namespace hipr::test
