// EXT_mesh_gpu_instancing: instances load as child nodes sharing one mesh, edit one by one or
// as a group, and save back into the extension (unchanged when unedited, rewritten when edited).
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <glm/gtc/matrix_transform.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gltf_document.h"
#include "hipr/edits.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

// The triangle shown three times, at x = 0, 2 and 4, the last one turned 90 degrees about z and
// scaled by 2.
fs::path instanced_triangle(const fs::path& dir) {
  test::Document doc = test::triangle_document();
  const int t =
      doc.add_accessor(std::vector<float>{0, 0, 0, 2, 0, 0, 4, 0, 0}, test::kFloat, "VEC3", 3);
  const float h = std::sqrt(0.5f);
  const int r = doc.add_accessor(std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, h, h},
                                 test::kFloat, "VEC4", 3);
  const int s =
      doc.add_accessor(std::vector<float>{1, 1, 1, 1, 1, 1, 2, 2, 2}, test::kFloat, "VEC3", 3);
  doc.gltf["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = {
      {"TRANSLATION", t}, {"ROTATION", r}, {"SCALE", s}};
  doc.gltf["extensionsUsed"] = {"EXT_mesh_gpu_instancing"};
  doc.gltf["extensionsRequired"] = {"EXT_mesh_gpu_instancing"};
  const fs::path file = dir / "instanced.gltf";
  test::write_document(file, doc);
  return file;
}

// World-space first vertex (1, 0, 0) of each visible instance, in instance order.
std::vector<glm::vec3> corners(const Scene& scene) {
  std::vector<glm::vec3> out;
  for (const Instance& i : scene.instances())
    if (i.visible) out.push_back(glm::vec3(i.world * glm::vec4(1, 0, 0, 1)));
  return out;
}

void expect_near(glm::vec3 a, glm::vec3 b) {
  EXPECT_LT(glm::length(a - b), 1e-5f) << a.x << " " << a.y << " " << a.z;
}

TEST(GpuInstancing, InstancesAreChildNodesSharingOneMesh) {
  const Scene scene = load_scene(instanced_triangle(test::temp_dir("instancing")));
  EXPECT_EQ(scene.meshes.size(), 1u);
  ASSERT_EQ(scene.instances().size(), 3u);
  const auto c = corners(scene);
  expect_near(c[0], {1, 0, 0});
  expect_near(c[1], {3, 0, 0});
  expect_near(c[2], {4, 2, 0});  // turned 90 degrees, twice as large
  EXPECT_EQ(scene.nodes[find_node(scene, "tri/1")].parent, int(find_node(scene, "tri")));
  EXPECT_TRUE(scene.nodes[find_node(scene, "tri/2")].gpu_instance);
}

TEST(GpuInstancing, EditedOneByOneOrAsAGroup) {
  Scene scene = load_scene(instanced_triangle(test::temp_dir("instancing_edit")));
  TransformEdit one;
  one.node = "tri/1";
  one.translate = glm::vec3(0, 1, 0);
  apply_edit(scene, one);
  TransformEdit all;
  all.node = "tri";
  all.translate = glm::vec3(0, 0, 5);
  apply_edit(scene, all);
  const auto c = corners(scene);
  expect_near(c[0], {1, 0, 5});
  expect_near(c[1], {3, 1, 5});
  expect_near(c[2], {4, 2, 5});
}

TEST(GpuInstancing, SavesBackIntoTheExtension) {
  const fs::path dir = test::temp_dir("instancing_save");
  Scene scene = load_scene(instanced_triangle(dir));
  // Unedited: the node keeps its extension as it was, and no instance becomes a node.
  save_scene(scene, dir / "unedited.gltf");
  json saved, source;
  std::ifstream(dir / "unedited.gltf") >> saved;
  std::ifstream(dir / "instanced.gltf") >> source;
  EXPECT_EQ(saved["nodes"], source["nodes"]);

  TransformEdit move;
  move.node = "tri/0";
  move.translate = glm::vec3(0, 0, -1);
  apply_edit(scene, move);
  apply_edit(scene, DeleteEdit{"tri/2"});
  apply_edit(scene, DuplicateEdit{"tri/1", "extra", glm::vec3(0, 3, 0)});
  save_scene(scene, dir / "edited.gltf");
  const Scene again = load_scene(dir / "edited.gltf");
  auto c = corners(again);
  ASSERT_EQ(c.size(), 3u);  // two instances, and the duplicate saved as a node of its own
  std::sort(c.begin(), c.end(),
            [](glm::vec3 a, glm::vec3 b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  expect_near(c[0], {1, 0, -1});
  expect_near(c[1], {3, 0, 0});
  expect_near(c[2], {3, 3, 0});
  EXPECT_EQ(again.meshes.size(), 1u);
}

TEST(GpuInstancing, BadAttributesAreOneLineErrors) {
  const fs::path dir = test::temp_dir("instancing_bad");
  json doc;
  std::ifstream(instanced_triangle(dir)) >> doc;
  std::vector<std::pair<std::string, json>> cases;
  json no_attributes = doc;
  no_attributes["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"] = json::object();
  cases.push_back({"no attributes", no_attributes});
  json counts = doc;
  counts["accessors"]
        [counts["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["SCALE"]
             .get<int>()]["count"] = 2;
  cases.push_back({"different counts", counts});
  json missing = doc;
  missing["nodes"][0]["extensions"]["EXT_mesh_gpu_instancing"]["attributes"]["ROTATION"] = 99;
  cases.push_back({"missing accessor", missing});
  for (const auto& [name, spoiled] : cases) {
    std::ofstream(dir / "bad.gltf") << spoiled.dump();
    try {
      load_scene(dir / "bad.gltf");
      ADD_FAILURE() << name << ": loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("EXT_mesh_gpu_instancing"), std::string::npos)
          << name << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace hipr
