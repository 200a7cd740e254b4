// The pose a file describes: morph targets at their default weights (mesh, then node; sparse
// targets too) and skins at their joints (the skinned node's own transform ignored, as glTF
// says), baked into the loaded vertices.
#include <gtest/gtest.h>

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "gltf_document.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

// World-space positions of the first instance's first primitive.
std::vector<glm::vec3> world_positions(const Scene& scene) {
  const Instance instance = scene.instances().at(0);
  std::vector<glm::vec3> out;
  for (const glm::vec3& p : scene.meshes[instance.mesh].primitives.at(0).positions)
    out.push_back(glm::vec3(instance.world * glm::vec4(p, 1.0f)));
  return out;
}

Scene load(const test::Document& doc, const std::string& name) {
  const fs::path file = test::temp_dir(name) / "scene.gltf";
  test::write_document(file, doc);
  return load_scene(file);
}

void expect_near(glm::vec3 a, glm::vec3 b, const std::string& what) {
  EXPECT_LT(glm::length(a - b), 1e-5f) << what << ": (" << a.x << ", " << a.y << ", " << a.z << ")";
}

// The triangle (0,0,0) (1,0,0) (0,1,0) with one target lifting its third vertex by 1 in z.
test::Document morphed_triangle(bool sparse) {
  test::Document doc = test::triangle_document();
  int target;
  if (sparse) {  // only vertex 2 listed; the rest zeros (no bufferView)
    const int values = doc.add_accessor(std::vector<float>{0, 0, 1}, test::kFloat, "VEC3", 1);
    const int indices =
        doc.add_accessor(std::vector<uint16_t>{2, 0}, test::kUnsignedShort, "SCALAR", 1);
    const json values_view = doc.gltf["accessors"][values]["bufferView"];
    const json indices_view = doc.gltf["accessors"][indices]["bufferView"];
    doc.gltf["accessors"].push_back(
        {{"componentType", test::kFloat},
         {"type", "VEC3"},
         {"count", 3},
         {"sparse",
          {{"count", 1},
           {"indices", {{"bufferView", indices_view}, {"componentType", test::kUnsignedShort}}},
           {"values", {{"bufferView", values_view}}}}}});
    target = int(doc.gltf["accessors"].size() - 1);
  } else {
    target =
        doc.add_accessor(std::vector<float>{0, 0, 0, 0, 0, 0, 0, 0, 1}, test::kFloat, "VEC3", 3);
  }
  doc.primitive()["targets"] = json::array({{{"POSITION", target}}});
  doc.gltf["meshes"][0]["weights"] = {0.5};
  return doc;
}

TEST(GltfPose, MorphTargetsAtTheMeshsDefaultWeights) {
  const Scene scene = load(morphed_triangle(false), "pose_morph");
  const auto p = world_positions(scene);
  expect_near(p[0], {0, 0, 0}, "vertex 0");
  expect_near(p[2], {0, 1, 0.5f}, "vertex 2 at weight 0.5");
}

TEST(GltfPose, NodeWeightsOverrideTheMeshsAndSparseTargetsApply) {
  test::Document doc = morphed_triangle(true);
  doc.gltf["nodes"][0]["weights"] = {1.0};
  const auto p = world_positions(load(doc, "pose_morph_node"));
  expect_near(p[1], {1, 0, 0}, "vertex 1");
  expect_near(p[2], {0, 1, 1}, "vertex 2 at the node's weight 1");
}

// Two joints: vertices 0 and 1 follow joint 0 (at the origin), vertex 2 follows joint 1, moved
// 2 up in z. The skinned node itself stands at x = 5, which glTF ignores for skinned meshes.
test::Document skinned_triangle() {
  test::Document doc = test::triangle_document();
  const int joints =
      doc.add_accessor(std::vector<uint8_t>{0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0}, 5121, "VEC4", 3);
  const int weights = doc.add_accessor(std::vector<float>{1, 0, 0, 0, 1, 0, 0, 0, 0.5f, 0.5f, 0, 0},
                                       test::kFloat, "VEC4", 3);
  doc.primitive()["attributes"]["JOINTS_0"] = joints;
  doc.primitive()["attributes"]["WEIGHTS_0"] = weights;
  // Joint 1's inverse bind matrix undoes its bind position (z = 1): the bind pose is the mesh.
  std::vector<float> binds = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0,  1,
                              1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, -1, 1};
  const int inverse_binds = doc.add_accessor(binds, test::kFloat, "MAT4", 2);
  doc.gltf["nodes"][0]["translation"] = {5, 0, 0};
  doc.gltf["nodes"][0]["skin"] = 0;
  doc.gltf["nodes"].push_back({{"name", "root_joint"}, {"children", {2}}});
  doc.gltf["nodes"].push_back({{"name", "tip_joint"}, {"translation", {0, 0, 3}}});
  doc.gltf["scenes"][0]["nodes"] = {0, 1};
  doc.gltf["skins"] = json::array({{{"joints", {1, 2}}, {"inverseBindMatrices", inverse_binds}}});
  return doc;
}

TEST(GltfPose, SkinsFollowTheirJointsNotTheSkinnedNode) {
  const auto p = world_positions(load(skinned_triangle(), "pose_skin"));
  expect_near(p[0], {0, 0, 0}, "vertex 0 (joint 0)");
  expect_near(p[1], {1, 0, 0}, "vertex 1 (joint 0)");
  // Half joint 0 (stays), half joint 1 (moved from its bind z = 1 to z = 3: +2).
  expect_near(p[2], {0, 1, 1}, "vertex 2 (half each)");
}

TEST(GltfPose, BadSkinsAreOneLineErrors) {
  std::vector<std::pair<std::string, test::Document>> cases;
  test::Document missing_joint = skinned_triangle();
  missing_joint.gltf["skins"][0]["joints"] = {1, 9};
  cases.push_back({"missing joint node", missing_joint});
  test::Document joint_index = skinned_triangle();
  joint_index.gltf["skins"][0]["joints"] = {1};  // vertex 2 names joint 1 of 1
  joint_index.gltf["skins"][0].erase("inverseBindMatrices");
  cases.push_back({"joint index past the skin", joint_index});
  test::Document missing_skin = skinned_triangle();
  missing_skin.gltf["nodes"][0]["skin"] = 4;
  cases.push_back({"missing skin", missing_skin});
  for (const auto& [name, doc] : cases) {
    try {
      load(doc, "pose_bad");
      ADD_FAILURE() << name << ": loaded";
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << name;
      EXPECT_NE(std::string(e.what()).find("skin"), std::string::npos) << name << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace hipr
