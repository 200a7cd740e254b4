// Geometry that breaks naive path tracers, at tiny, unit and huge scale: zero-area and sliver
// triangles (some of them emitters of 1e6 nits, so they enter the light table), two coincident
// faces with different materials, a light sealed inside a closed box, and a camera skimming
// the floor at a grazing angle. Every sample must stay finite.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "hipr/renderer.h"
#include "test_support.h"

namespace hipr {
namespace {

// Appends triangle (a, b, c) with flat, possibly degenerate, shading attributes.
void add_triangle(MeshPrimitive& p, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
  glm::vec3 n = glm::cross(b - a, c - a);
  n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
  for (const glm::vec3& v : {a, b, c}) {
    p.indices.push_back(uint32_t(p.positions.size()));
    p.positions.push_back(v);
    p.normals.push_back(n);
    p.tangents.emplace_back(1.0f, 0.0f, 0.0f, 1.0f);
    p.uvs.emplace_back(v.x, v.z);
  }
}

void add_quad(MeshPrimitive& p, glm::vec3 o, glm::vec3 u, glm::vec3 v) {
  add_triangle(p, o, o + u, o + u + v);
  add_triangle(p, o, o + u + v, o + v);
}

// An axis-aligned box with outward faces.
void add_box(MeshPrimitive& p, glm::vec3 lo, glm::vec3 hi) {
  const glm::vec3 d = hi - lo;
  const glm::vec3 x(d.x, 0, 0), y(0, d.y, 0), z(0, 0, d.z);
  add_quad(p, lo, z, x);      // bottom (-y)
  add_quad(p, lo + y, x, z);  // top (+y)
  add_quad(p, lo, y, z);      // -x
  add_quad(p, lo + x, z, y);  // +x
  add_quad(p, lo, x, y);      // -z
  add_quad(p, lo + z, y, x);  // +z
}

Material material(const char* name, glm::vec3 color, float emission = 0.0f) {
  Material m;
  m.name = name;
  m.params = default_material_params();
  m.params.base_color = color;
  m.params.specular_roughness = 0.3f;
  m.params.emission_color = glm::vec3(1.0f);
  m.params.emission_luminance = emission;
  return m;
}

Scene stress_scene(float scale) {
  Scene scene;
  scene.materials = {material("floor", glm::vec3(0.8f)),
                     material("coincident", glm::vec3(0.8f, 0.1f, 0.1f)),
                     material("hot", glm::vec3(0.0f), 1e6f), material("box", glm::vec3(0.5f))};
  scene.materials[1].params.base_metalness = 1.0f;

  MeshPrimitive floor, coincident, hot, box;
  floor.material = 0;
  coincident.material = 1;
  hot.material = 2;
  box.material = 3;
  add_quad(floor, glm::vec3(-2, 0, -2), glm::vec3(0, 0, 4), glm::vec3(4, 0, 0));
  add_quad(coincident, glm::vec3(-1, 0, -1), glm::vec3(0, 0, 2),
           glm::vec3(2, 0, 0));  // in the floor's plane
  add_triangle(hot, glm::vec3(0.3f, 0.5f, 0.0f), glm::vec3(0.3f, 0.5f, 0.0f),
               glm::vec3(0.3f, 0.5f, 0.0f));
  add_triangle(hot, glm::vec3(-0.5f, 0.4f, 0.0f), glm::vec3(0.0f, 0.4f, 0.0f),
               glm::vec3(0.5f, 0.4f, 0.0f));
  add_triangle(hot, glm::vec3(-1.0f, 0.6f, -0.5f), glm::vec3(1.0f, 0.6f, -0.5f),
               glm::vec3(0.0f, 0.6f + 1e-6f, -0.5f));
  add_box(box, glm::vec3(0.4f, 0.0f, 0.4f), glm::vec3(0.7f, 0.3f, 0.7f));
  add_triangle(hot, glm::vec3(0.5f, 0.1f, 0.5f), glm::vec3(0.6f, 0.1f, 0.5f),
               glm::vec3(0.55f, 0.1f, 0.6f));  // sealed in
  scene.meshes.push_back({"stress", {floor, coincident, hot, box}});

  PunctualLight sealed;
  sealed.name = "sealed";
  sealed.intensity = 1e4f;
  scene.lights.push_back(sealed);

  const glm::mat4 world = glm::scale(glm::mat4(1.0f), glm::vec3(scale));
  Node geometry;
  geometry.name = "stress";
  geometry.mesh = 0;
  geometry.local = world;
  Node light;
  light.name = "sealed";
  light.light = 0;
  light.local = world * glm::translate(glm::mat4(1.0f), glm::vec3(0.55f, 0.2f, 0.55f));
  Node camera;
  camera.name = "camera";
  camera.camera = 0;
  camera.local =
      world * glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.002f, 3.0f));  // skims the floor
  scene.nodes = {geometry, light, camera};
  scene.children = {{}, {}, {}};
  scene.root_nodes = {0, 1, 2};
  scene.cameras.push_back(Camera{});
  scene.environment = test::uniform_environment(1.0f);
  return scene;
}

class GeometryStress : public ::testing::TestWithParam<float> {};

TEST_P(GeometryStress, NoNonFiniteSamples) {
  RenderSettings s;
  s.width = s.height = 32;
  s.max_depth = 16;
  s.seed = 11;
  EXPECT_GT(test::mean(test::render_finite(stress_scene(GetParam()), s, 8)), 0.1)
      << "the sky and the lit floor must show";
}

INSTANTIATE_TEST_SUITE_P(Scales, GeometryStress, ::testing::Values(1e-4f, 1.0f, 1e5f));

}  // namespace
}  // namespace hipr
