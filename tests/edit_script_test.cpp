// Edit scripts, applying edits and the scene diff (no GPU).
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "test_support.h"

namespace hipr {
namespace {

Scene cornell() { return load_scene(test::asset("cornell_box.gltf")); }

size_t instance_of(const Scene& scene, const std::string& node) {
  const auto instances = scene.instances();
  for (size_t i = 0; i < instances.size(); ++i)
    if (scene.nodes[instances[i].node].name == node) return i;
  return SIZE_MAX;
}

void expect_input_error(const std::string& json, const std::string& needle) {
  try {
    parse_edit_script(json, "edits.json");
    FAIL() << "accepted: " << json;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("edits.json"), std::string::npos) << e.what();
  }
}

TEST(EditScript, ShippedScriptsParseAndApply) {
  for (const char* name : {"cornell_box", "cornell_sphere"}) {
    Scene scene = load_scene(test::asset(std::string(name) + (std::string(name) == "cornell_box" ? ".gltf" : ".glb")));
    const auto edits = load_edit_script(test::asset(std::string(name) + ".edits.json"));
    ASSERT_FALSE(edits.empty());
    for (const Edit& edit : edits) EXPECT_NO_THROW(apply_edit(scene, edit)) << describe(edit);
  }
}

TEST(EditScript, BadScriptsNameTheProblem) {
  expect_input_error("{", "invalid JSON");
  expect_input_error("{\"edits\": 3}", "array");
  expect_input_error(R"({"edits": [{"op": "paint"}]})", "unknown op");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a"}]})", "translate");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "translate": [1, 2]}]})", "3 numbers");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "translate": [0,0,0], "scale": 2}]})", "scale");
  expect_input_error(R"({"edits": [{"op": "material", "material": "red", "set": {"colour": [1,0,0]}}]})", "colour");
  expect_input_error(R"({"edits": [{"op": "material", "material": "red", "set": {"base_color": [2,0,0]}}]})", "outside");
  expect_input_error(R"({"edits": [{"op": "emission", "material": "light", "set": {"base_color": [1,1,1]}}]})", "emission");
  expect_input_error(R"({"edits": [{"op": "light", "node": "lamp", "set": {"watts": 3}}]})", "watts");
  expect_input_error(R"({"edits": [{"op": "visibility", "node": "a", "visible": "no"}]})", "boolean");
}

TEST(EditScript, UnknownNamesAreErrorsNamingThem) {
  Scene scene = cornell();
  for (const char* json : {R"({"edits": [{"op": "transform", "node": "teapot", "translate": [0,0,0]}]})",
                           R"({"edits": [{"op": "material", "material": "teapot", "set": {"base_color": [1,1,1]}}]})",
                           R"({"edits": [{"op": "light", "node": "teapot", "set": {"intensity": 1}}]})"}) {
    const auto edits = parse_edit_script(json, "edits.json");
    try {
      apply_edit(scene, edits[0]);
      FAIL() << json;
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("teapot"), std::string::npos);
    }
  }
}

TEST(Edits, TransformAddsToTheLocalTranslation) {
  Scene scene = cornell();
  const size_t node = [&] {
    for (size_t n = 0; n < scene.nodes.size(); ++n)
      if (scene.nodes[n].name == "tall_block") return n;
    return size_t(0);
  }();
  const glm::vec3 start = glm::vec3(scene.nodes[node].local[3]);
  apply_edit(scene, parse_edit_script(R"({"edits": [{"op": "transform", "node": "tall_block", "translate": [0.06, 0, -0.08]}]})", "e")[0]);
  EXPECT_EQ(glm::vec3(scene.nodes[node].local[3]), start + glm::vec3(0.06f, 0.0f, -0.08f));
  // "#index" names nodes by position.
  apply_edit(scene, TransformEdit{"#" + std::to_string(node), glm::vec3(1, 0, 0), std::nullopt});
  EXPECT_NEAR(scene.nodes[node].local[3].x, start.x + 1.06f, 1e-6f);
}

TEST(SceneDiff, EachKindOfEditReportsItsChange) {
  const Scene base = cornell();
  {
    Scene s = base;
    apply_edit(s, TransformEdit{"tall_block", glm::vec3(0.1f, 0, 0), std::nullopt});
    const ChangeSet c = diff_scenes(base, s);
    EXPECT_TRUE(c.transforms);
    EXPECT_FALSE(c.materials);
    EXPECT_FALSE(c.light_tables);  // the block is not emissive
    ASSERT_EQ(c.instances.size(), 1u);
    EXPECT_EQ(c.instances[0], instance_of(base, "tall_block"));
  }
  {
    Scene s = base;
    apply_edit(s, MaterialEdit{"white", {{"base_color", {0.5f, 0.5f, 0.5f}}}});
    const ChangeSet c = diff_scenes(base, s);
    EXPECT_TRUE(c.materials);
    EXPECT_FALSE(c.transforms);
    EXPECT_EQ(c.instances.size(), 5u);  // floor, ceiling, back wall, two blocks
  }
  {
    Scene s = base;
    apply_edit(s, MaterialEdit{"light", {{"emission_luminance", {30.0f}}}});
    const ChangeSet c = diff_scenes(base, s);
    EXPECT_TRUE(c.materials);
    EXPECT_TRUE(c.light_tables);
    ASSERT_EQ(c.instances.size(), 1u);
    EXPECT_EQ(c.instances[0], instance_of(base, "light"));
  }
  {
    Scene s = base;
    apply_edit(s, VisibilityEdit{"short_block", false});
    const ChangeSet c = diff_scenes(base, s);
    EXPECT_TRUE(c.transforms);
    ASSERT_EQ(c.instances.size(), 1u);
    EXPECT_FALSE(s.instances()[c.instances[0]].visible);
  }
  {
    Scene s = base;
    apply_edit(s, CameraEdit{glm::vec3(0, 0, -0.1f), std::nullopt});
    const ChangeSet c = diff_scenes(base, s);
    EXPECT_TRUE(c.camera);
    EXPECT_TRUE(c.instances.empty());
  }
  EXPECT_TRUE(diff_scenes(base, base).empty());
}

TEST(SceneDiff, PunctualLightEdit) {
  const Scene base = load_scene(test::asset("cornell_sphere.glb"));
  Scene s = base;
  apply_edit(s, LightEdit{"lamp", 2.0f, glm::vec3(1, 0.9f, 0.8f), std::nullopt});
  const ChangeSet c = diff_scenes(base, s);
  EXPECT_TRUE(c.light_tables);
  EXPECT_EQ(c.lights.size(), 1u);
  EXPECT_TRUE(c.instances.empty());
}

}  // namespace
}  // namespace hipr
