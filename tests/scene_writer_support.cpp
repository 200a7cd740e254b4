#include "scene_writer_support.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "scene/default_camera.h"
#include "scene/material_parameters.h"

namespace hipr::test {

namespace {

std::vector<float> field(const MaterialParameters& m, const MaterialParameter& p) {
  std::vector<float> v(static_cast<size_t>(p.components));
  std::memcpy(v.data(), reinterpret_cast<const char*>(&m) + p.offset, v.size() * sizeof(float));
  return v;
}

}  // namespace

void expect_same_scene(const Scene& want, const Scene& got, bool same_extensions) {
  // A scene without a camera is saved with its default view as a camera node, appended last
  // (docs/method.md, "Units and conventions"), which renders the same view; the rest is as it was.
  const bool saved_view = want.camera_node() < 0 && got.nodes.size() == want.nodes.size() + 1;
  if (saved_view) {
    EXPECT_EQ(got.nodes.back().name, "default_camera");
    EXPECT_EQ(got.camera_node(), int(got.nodes.size() - 1));
    EXPECT_EQ(resolve_camera(got).camera_to_world, resolve_camera(want).camera_to_world);
  }
  ASSERT_EQ(want.nodes.size() + (saved_view ? 1 : 0), got.nodes.size());
  for (size_t i = 0; i < want.nodes.size(); ++i) {
    const Node &a = want.nodes[i], &b = got.nodes[i];
    SCOPED_TRACE("node " + std::to_string(i) + " '" + a.name + "'");
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.parent, b.parent);
    EXPECT_EQ(a.mesh, b.mesh);
    EXPECT_EQ(a.camera, b.camera);
    EXPECT_EQ(a.light, b.light);
    EXPECT_EQ(a.visible, b.visible);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        EXPECT_EQ(a.local[c][r], b.local[c][r]) << "local[" << c << "][" << r << "]";
  }
  std::vector<uint32_t> roots = got.root_nodes;
  std::vector<std::vector<uint32_t>> children = got.children;
  if (saved_view && !roots.empty() && roots.back() == got.nodes.size() - 1) roots.pop_back();
  if (saved_view && children.size() == got.nodes.size()) children.pop_back();
  EXPECT_EQ(want.root_nodes, roots);
  EXPECT_EQ(want.children, children);

  ASSERT_EQ(want.meshes.size(), got.meshes.size());
  for (size_t i = 0; i < want.meshes.size(); ++i) {
    ASSERT_EQ(want.meshes[i].primitives.size(), got.meshes[i].primitives.size());
    EXPECT_EQ(want.meshes[i].name, got.meshes[i].name);
    for (size_t p = 0; p < want.meshes[i].primitives.size(); ++p) {
      const MeshPrimitive &a = want.meshes[i].primitives[p], &b = got.meshes[i].primitives[p];
      SCOPED_TRACE("mesh " + std::to_string(i) + " primitive " + std::to_string(p));
      EXPECT_EQ(a.material, b.material);
      EXPECT_TRUE(a.positions == b.positions);
      EXPECT_TRUE(a.normals == b.normals);
      EXPECT_TRUE(a.tangents == b.tangents);
      EXPECT_TRUE(a.uvs == b.uvs);
      EXPECT_TRUE(a.uvs1 == b.uvs1);
      EXPECT_EQ(a.indices, b.indices);
    }
  }

  ASSERT_EQ(want.materials.size(), got.materials.size());
  for (size_t i = 0; i < want.materials.size(); ++i) {
    const Material &a = want.materials[i], &b = got.materials[i];
    SCOPED_TRACE("material " + std::to_string(i) + " '" + a.name + "'");
    EXPECT_EQ(a.name, b.name);
    for (const MaterialParameter& p : material_parameters())
      EXPECT_EQ(field(a.params, p), field(b.params, p)) << p.name;
    // Everything else of the block (flags, cutoff, scales, texture slots) too, to the byte.
    EXPECT_EQ(std::memcmp(&a.params, &b.params, sizeof(MaterialParameters)), 0);
  }
  ASSERT_EQ(want.textures.size(), got.textures.size());
  for (size_t i = 0; i < want.textures.size(); ++i) {
    EXPECT_EQ(want.textures[i].image, got.textures[i].image);
    EXPECT_EQ(want.textures[i].flags, got.textures[i].flags);
    EXPECT_TRUE(want.textures[i].uv_transform_u == got.textures[i].uv_transform_u);
    EXPECT_TRUE(want.textures[i].uv_transform_v == got.textures[i].uv_transform_v);
  }
  ASSERT_EQ(want.images.size(), got.images.size());
  for (size_t i = 0; i < want.images.size(); ++i) {
    EXPECT_EQ(want.images[i].width, got.images[i].width);
    EXPECT_EQ(want.images[i].height, got.images[i].height);
    EXPECT_TRUE(want.images[i].rgba8 == got.images[i].rgba8) << "image " << i;
  }
  ASSERT_EQ(want.lights.size(), got.lights.size());
  for (size_t i = 0; i < want.lights.size(); ++i) {
    const PunctualLight &a = want.lights[i], &b = got.lights[i];
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.type, b.type);
    EXPECT_TRUE(a.color == b.color) << "light " << i;
    EXPECT_EQ(a.intensity, b.intensity);
    EXPECT_EQ(a.range, b.range);
    EXPECT_EQ(a.inner_cone, b.inner_cone);
    EXPECT_EQ(a.outer_cone, b.outer_cone);
  }
  ASSERT_EQ(want.cameras.size() + (saved_view ? 1 : 0), got.cameras.size());
  for (size_t i = 0; i < want.cameras.size(); ++i) {
    EXPECT_EQ(want.cameras[i].name, got.cameras[i].name);
    EXPECT_EQ(want.cameras[i].yfov, got.cameras[i].yfov);
    EXPECT_EQ(want.cameras[i].znear, got.cameras[i].znear);
  }
  if (!saved_view) {
    EXPECT_EQ(want.camera_node(), got.camera_node());
  }
  if (same_extensions) {
    EXPECT_EQ(want.extensions_used, got.extensions_used);
  }
}

MaterialEdit every_parameter_edit(const std::string& material, int variant) {
  MaterialEdit edit{material, {}};
  int k = 0;
  for (const MaterialParameter& p : material_parameters()) {
    const float lo = std::isfinite(p.min) ? p.min : -3.0f;
    const float hi = std::isfinite(p.max) ? p.max : lo + 5.0f;
    ParameterValue value{p.name, {}};
    for (int c = 0; c < p.components; ++c) {
      const double step = variant == 1 ? 0.618034 * (k + 1) + 0.29 * c : 0.377 * (k + 3) + 0.51 * c;
      const float f = variant == 0 ? 0.0f : float(0.1 + 0.8 * (step - std::floor(step)));
      value.values.push_back(lo + f * (hi - lo));
    }
    edit.set.push_back(value);
    ++k;
  }
  return edit;
}

std::vector<Edit> typical_edits(const Scene& scene) {
  std::vector<Edit> edits;
  int first_mesh = -1, last_mesh = -1, light = -1;
  for (size_t i = 0; i < scene.nodes.size(); ++i) {
    if (scene.nodes[i].mesh >= 0) {
      if (first_mesh < 0) first_mesh = int(i);
      last_mesh = int(i);
    }
    if (scene.nodes[i].light >= 0 && light < 0) light = int(i);
  }
  const auto [lo, hi] = scene.bounds();
  const float size = glm::length(hi - lo);
  if (first_mesh >= 0)
    edits.push_back(TransformEdit{"#" + std::to_string(first_mesh),
                                  glm::vec3(0.05f, 0.02f, -0.03f) * size, std::nullopt});
  if (last_mesh >= 0) edits.push_back(VisibilityEdit{"#" + std::to_string(last_mesh), false});
  edits.push_back(MaterialEdit{"#0",
                               {{"base_color", {0.2f, 0.4f, 0.6f}},
                                {"specular_roughness", {0.35f}},
                                {"coat_darkening", {0.3f}},
                                {"base_diffuse_roughness", {0.5f}}}});
  if (light >= 0) {
    const PunctualLight& l = scene.lights[size_t(scene.nodes[size_t(light)].light)];
    edits.push_back(LightEdit{"#" + std::to_string(light), l.intensity * 2.0f,
                              glm::vec3(1.0f, 0.5f, 0.25f), 10.0f});
  }
  edits.push_back(CameraEdit{glm::vec3(0.0f, 0.01f, 0.02f) * size, std::nullopt});
  return edits;
}

std::vector<SharedScene> shared_scenes_to_save() {
  return {{"CornellBox/cornellBox.gltf"},
          {"SheenChair/SheenChair.gltf"},
          {"LightsPunctualLamp/LightsPunctualLamp.gltf"},
          {"DamagedHelmet/DamagedHelmet.glb"}};
}

}  // namespace hipr::test
