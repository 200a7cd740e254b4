// Edit scripts, applying edits and the scene diff (no GPU).
#include <gtest/gtest.h>

#include <cstring>

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
    Scene scene = load_scene(
        test::asset(std::string(name) + (std::string(name) == "cornell_box" ? ".gltf" : ".glb")));
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
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "translate": [1, 2]}]})",
                     "3 numbers");
  expect_input_error(
      R"({"edits": [{"op": "transform", "node": "a", "translate": [0,0,0], "scale": 2}]})",
      "scale");
  expect_input_error(
      R"({"edits": [{"op": "material", "material": "red", "set": {"colour": [1,0,0]}}]})",
      "colour");
  expect_input_error(
      R"({"edits": [{"op": "material", "material": "red", "set": {"base_color": [2,0,0]}}]})",
      "outside");
  expect_input_error(
      R"({"edits": [{"op": "emission", "material": "light", "set": {"base_color": [1,1,1]}}]})",
      "emission");
  expect_input_error(R"({"edits": [{"op": "light", "node": "lamp", "set": {"watts": 3}}]})",
                     "watts");
  expect_input_error(R"({"edits": [{"op": "visibility", "node": "a", "visible": "no"}]})",
                     "boolean");
}

TEST(EditScript, UnknownNamesAreErrorsNamingThem) {
  Scene scene = cornell();
  for (const char* json :
       {R"({"edits": [{"op": "transform", "node": "teapot", "translate": [0,0,0]}]})",
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
  apply_edit(
      scene,
      parse_edit_script(
          R"({"edits": [{"op": "transform", "node": "tall_block", "translate": [0.06, 0, -0.08]}]})",
          "e")[0]);
  EXPECT_EQ(glm::vec3(scene.nodes[node].local[3]), start + glm::vec3(0.06f, 0.0f, -0.08f));
  // "#index" names nodes by position.
  apply_edit(scene, TransformEdit{"#" + std::to_string(node), glm::vec3(1, 0, 0), std::nullopt});
  EXPECT_NEAR(scene.nodes[node].local[3].x, start.x + 1.06f, 1e-6f);
}

size_t node_named(const Scene& scene, const std::string& name) {
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    if (scene.nodes[n].name == name) return n;
  return SIZE_MAX;
}

void expect_near(const glm::mat4& a, const glm::mat4& b, float tolerance) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(a[c][r], b[c][r], tolerance) << c << " " << r;
}

// "rotate" turns about the parent's axes through the node's own origin, "scale" stretches along
// the node's own axes, both composed with what the node had (and with "translate").
TEST(Edits, RotateAndScaleComposeWithTheNodesTransform) {
  Scene scene = cornell();
  const size_t node = node_named(scene, "tall_block");
  const glm::mat4 start = scene.nodes[node].local;
  apply_edit(scene, parse_edit_script(R"({"edits": [{"op": "transform", "node": "tall_block",
                                         "rotate": [0, 90, 0]}]})",
                                      "e")[0]);
  const glm::mat4 turned = scene.nodes[node].local;
  EXPECT_EQ(glm::vec3(turned[3]), glm::vec3(start[3])) << "about the node's own origin";
  glm::mat4 expected = glm::rotate(glm::mat4(1.0f), glm::radians(90.0f), glm::vec3(0, 1, 0)) *
                       glm::mat4(glm::mat3(start));
  expected[3] = start[3];
  expect_near(turned, expected, 1e-5f);

  apply_edit(scene, parse_edit_script(R"({"edits": [{"op": "transform", "node": "tall_block",
                                         "scale": [2, 1, 1], "translate": [0.1, 0, 0]}]})",
                                      "e")[0]);
  const glm::mat4 scaled = scene.nodes[node].local;
  EXPECT_NEAR(glm::length(glm::vec3(scaled[0])), 2.0f * glm::length(glm::vec3(turned[0])), 1e-5f)
      << "x stretched along the node's own x";
  EXPECT_NEAR(glm::length(glm::vec3(scaled[1])), glm::length(glm::vec3(turned[1])), 1e-5f);
  EXPECT_NEAR(glm::dot(glm::vec3(scaled[0]), glm::vec3(scaled[2])), 0.0f, 1e-5f) << "no shear";
  EXPECT_NEAR(scaled[3].x, turned[3].x + 0.1f, 1e-6f);

  // Undo is the node's matrix as it was.
  const Edit undo = inverse_edit(scene, TransformEdit{"tall_block", {}, {}, glm::vec3(1), {}});
  EXPECT_EQ(std::get<TransformEdit>(undo).matrix, scaled);
}

TEST(EditScript, BadRotateAndScaleAreRefused) {
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "scale": [0, 1, 1]}]})",
                     "scale factor");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "scale": [1, 1e9, 1]}]})",
                     "scale factor");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "rotate": [0, 1e7, 0]}]})",
                     "rotate");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "rotate": [0, 90]}]})",
                     "3 numbers");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "rotate": [0, "x", 0]}]})",
                     "numbers");
  expect_input_error(R"({"edits": [{"op": "transform", "node": "a", "rotate": [0, 9, 0],
                         "matrix": [1,0,0,0, 0,1,0,0, 0,0,1,0, 0,0,0,1]}]})",
                     "alone");
  // Made in code (the viewer's way), the same factor is refused as the edit applies.
  Scene scene = cornell();
  EXPECT_THROW(apply_edit(scene, TransformEdit{"tall_block", {}, {}, {}, glm::vec3(1, 0, 1)}),
               InputError);
}

TEST(EditScript, CameraOpsSwitchAndOpenTheLens) {
  const auto edits = parse_edit_script(R"({"edits": [
      {"op": "camera", "use": "camera"},
      {"op": "camera", "aperture": 0.01, "focus_distance": 2.5},
      {"op": "camera", "translate": [0, 0, 0.1], "focus_distance": 1}]})",
                                       "e");
  ASSERT_EQ(edits.size(), 3u);
  EXPECT_EQ(std::get<CameraEdit>(edits[0]).use, "camera");
  EXPECT_EQ(std::get<CameraEdit>(edits[1]).aperture_radius, 0.01f);
  EXPECT_EQ(std::get<CameraEdit>(edits[1]).focus_distance, 2.5f);
  Scene scene = cornell();
  for (const Edit& edit : edits) apply_edit(scene, edit);
  EXPECT_EQ(scene.cameras[0].aperture_radius, 0.01f);
  EXPECT_EQ(scene.cameras[0].focus_distance, 1.0f);
  expect_input_error(R"({"edits": [{"op": "camera", "aperture": -1}]})", "aperture");
  expect_input_error(R"({"edits": [{"op": "camera", "focus_distance": 0}]})", "focus_distance");
  expect_input_error(R"({"edits": [{"op": "camera", "use": "a", "aperture": 0.1}]})", "alone");
  expect_input_error(R"({"edits": [{"op": "camera", "use": 3}]})", "use");
  expect_input_error(R"({"edits": [{"op": "camera"}]})", "aperture");
}

// The Selection panel's fields: a local transform taken apart and put back together.
TEST(Edits, LocalPoseRoundTrips) {
  const glm::vec3 rotations[] = {
      {0, 0, 0}, {10, -20, 30}, {0, 90, 0}, {45, -90, 10}, {170, 5, -60}};
  const glm::vec3 scales[] = {{1, 1, 1}, {2, 0.5f, 3}, {-1, 1, 1}};
  for (const glm::vec3& rotation : rotations)
    for (const glm::vec3& scale : scales) {
      const glm::mat4 m = compose_pose({glm::vec3(1, -2, 3), rotation, scale});
      const LocalPose pose = local_pose(m);
      expect_near(compose_pose(pose), m, 1e-4f);
      EXPECT_NEAR(pose.scale.y, scale.y, 1e-5f);
    }
  const LocalPose turned = local_pose(euler_rotation(glm::vec3(0, 90, 0)));
  EXPECT_NEAR(turned.rotation_degrees.y, 90.0f, 1e-3f);
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

// A scene with an environment: the furnace sphere under a uniform sky.
Scene sky_scene() { return test::make_furnace_scene(0.5f, glm::vec3(0.0f), 0.8f, 1.0f); }

TEST(EditScript, EnvironmentOpSetsIntensityAndRotationInDegrees) {
  const auto edits = parse_edit_script(
      R"({"edits": [{"op": "environment", "set": {"intensity": 2.5, "rotation": 90}}]})", "e");
  ASSERT_EQ(edits.size(), 1u);
  const auto* e = std::get_if<EnvironmentEdit>(&edits[0]);
  ASSERT_NE(e, nullptr);
  EXPECT_EQ(e->intensity, 2.5f);
  EXPECT_FLOAT_EQ(*e->rotation, glm::radians(90.0f));
  Scene scene = sky_scene();
  apply_edit(scene, edits[0]);
  EXPECT_EQ(scene.environment->intensity, 2.5f);
  EXPECT_FLOAT_EQ(scene.environment->rotation, glm::radians(90.0f));
  EXPECT_EQ(describe(edits[0]), "environment");
  // One key alone leaves the other as it was.
  apply_edit(scene, parse_edit_script(
                        R"({"edits": [{"op": "environment", "set": {"intensity": 0}}]})", "e")[0]);
  EXPECT_EQ(scene.environment->intensity, 0.0f);
  EXPECT_FLOAT_EQ(scene.environment->rotation, glm::radians(90.0f));
}

TEST(EditScript, BadEnvironmentEditsNameTheProblem) {
  expect_input_error(R"({"edits": [{"op": "environment", "set": {"intensity": -1}}]})",
                     "intensity");
  expect_input_error(R"({"edits": [{"op": "environment", "set": {"rotation": [1, 2]}}]})",
                     "rotation");
  expect_input_error(R"({"edits": [{"op": "environment", "set": {"exposure": 1}}]})", "exposure");
  expect_input_error(R"({"edits": [{"op": "environment", "set": {}}]})", "set");
  expect_input_error(
      R"({"edits": [{"op": "environment", "node": "sky", "set": {"intensity": 1}}]})", "node");
  // A scene without an environment map cannot be given one's intensity.
  Scene scene = cornell();
  const auto edits =
      parse_edit_script(R"({"edits": [{"op": "environment", "set": {"intensity": 2}}]})", "e");
  EXPECT_THROW(apply_edit(scene, edits[0]), InputError);
}

// Focus ops (docs/method.md#focus): seeds for HiPR's order, not changes of the scene.
TEST(EditScript, FocusOpsParseAndChangeNoScene) {
  const auto edits = parse_edit_script(R"({"edits": [
      {"op": "focus", "node": "tall_block"},
      {"op": "focus", "pixel": [12, 40.5], "radius": 8, "weight": 2.5},
      {"op": "focus", "node": "short_block", "pixel": [1, 2], "radius": 3},
      {"op": "focus", "clear": true}]})",
                                       "e");
  ASSERT_EQ(edits.size(), 4u);
  const auto& node = std::get<FocusEdit>(edits[0]);
  EXPECT_EQ(node.node, "tall_block");
  EXPECT_FALSE(node.pixel);
  EXPECT_EQ(node.weight, 1.0f);
  const auto& disc = std::get<FocusEdit>(edits[1]);
  EXPECT_EQ(disc.pixel, glm::vec2(12.0f, 40.5f));
  EXPECT_EQ(disc.radius, 8.0f);
  EXPECT_EQ(disc.weight, 2.5f);
  EXPECT_TRUE(std::get<FocusEdit>(edits[3]).clear);
  EXPECT_EQ(describe(edits[0]), "focus tall_block");
  EXPECT_EQ(describe(edits[1]), "focus pixel (12, 40.5) radius 8");
  EXPECT_EQ(describe(edits[3]), "focus clear");
  const Scene base = cornell();
  Scene scene = base;
  for (const Edit& edit : edits) {
    EXPECT_TRUE(is_focus(edit));
    apply_edit(scene, inverse_edit(scene, edit));
    apply_edit(scene, edit);
    EXPECT_TRUE(diff_scenes(base, scene).empty()) << describe(edit);
  }
  EXPECT_THROW(apply_edit(scene, FocusEdit{.node = "nowhere"}), InputError);
}

TEST(EditScript, BadFocusOpsNameTheProblem) {
  expect_input_error(R"({"edits": [{"op": "focus"}]})", "needs");
  expect_input_error(R"({"edits": [{"op": "focus", "pixel": [1, 2]}]})", "radius");
  expect_input_error(R"({"edits": [{"op": "focus", "pixel": [1, 2], "radius": 0}]})", "radius");
  expect_input_error(R"({"edits": [{"op": "focus", "pixel": [1], "radius": 3}]})", "pixel");
  expect_input_error(R"({"edits": [{"op": "focus", "radius": 3, "node": "a"}]})", "radius");
  expect_input_error(R"({"edits": [{"op": "focus", "node": "a", "weight": 0}]})", "weight");
  expect_input_error(R"({"edits": [{"op": "focus", "node": "a", "weight": 1e9}]})", "weight");
  expect_input_error(R"({"edits": [{"op": "focus", "clear": false}]})", "clear");
  expect_input_error(R"({"edits": [{"op": "focus", "clear": true, "node": "a"}]})", "clear");
  expect_input_error(R"({"edits": [{"op": "focus", "node": "a", "zoom": 2}]})", "zoom");
}

TEST(SceneDiff, EnvironmentEditRestartsEverythingAndRebuildsLightTables) {
  const Scene base = sky_scene();
  Scene s = base;
  apply_edit(s, EnvironmentEdit{.rotation = 0.5f});
  ChangeSet c = diff_scenes(base, s);
  EXPECT_TRUE(c.environment);
  EXPECT_TRUE(c.light_tables);  // the environment's share of light selection follows its power
  EXPECT_TRUE(c.instances.empty());
  EXPECT_FALSE(c.empty());
  s = base;
  apply_edit(s, EnvironmentEdit{.intensity = 3.0f});
  EXPECT_TRUE(diff_scenes(base, s).environment);
  EXPECT_FALSE(diff_scenes(base, base).environment);
}

TEST(EditScript, EnvironmentSourceAndSun) {
  const auto edits = parse_edit_script(R"({"edits": [
      {"op": "environment", "source": "sky", "set": {"sun_elevation": 20, "turbidity": 4}},
      {"op": "environment", "set": {"sun_azimuth": -45}},
      {"op": "environment", "source": "maps/room.hdr"},
      {"op": "environment", "source": "none"}]})",
                                       "e", "/scripts");
  ASSERT_EQ(edits.size(), 4u);
  const auto& sky = std::get<EnvironmentEdit>(edits[0]);
  EXPECT_EQ(sky.source, std::filesystem::path("sky"));  // built-in names are not paths
  EXPECT_EQ(sky.sun_elevation_degrees, 20.0f);
  EXPECT_EQ(sky.turbidity, 4.0f);
  EXPECT_FALSE(sky.sun_azimuth_degrees.has_value());
  EXPECT_EQ(describe(edits[0]), "environment sky");
  EXPECT_EQ(std::get<EnvironmentEdit>(edits[1]).sun_azimuth_degrees, -45.0f);
  EXPECT_EQ(describe(edits[1]), "environment sun");
  // A file is relative to the script's folder (confinement:
  // EnvironmentFilesStayInTheScriptsFolder).
  EXPECT_EQ(std::get<EnvironmentEdit>(edits[2]).source,
            std::filesystem::path("/scripts/maps/room.hdr"));
  EXPECT_EQ(std::get<EnvironmentEdit>(edits[3]).source, std::filesystem::path("none"));
}

TEST(EditScript, BadEnvironmentSwitchesNameTheProblem) {
  expect_input_error(R"({"edits": [{"op": "environment"}]})", "source");
  expect_input_error(R"({"edits": [{"op": "environment", "source": ""}]})", "source");
  expect_input_error(R"({"edits": [{"op": "environment", "source": 3}]})", "source");
  expect_input_error(
      R"({"edits": [{"op": "environment", "source": "studio", "set": {"turbidity": 3}}]})", "sky");
  expect_input_error(
      R"({"edits": [{"op": "environment", "source": "sky", "set": {"turbidity": 11}}]})",
      "turbidity");
  expect_input_error(
      R"({"edits": [{"op": "environment", "source": "sky", "set": {"sun_elevation": 95}}]})",
      "sun_elevation");
  expect_input_error(R"({"edits": [{"op": "environment", "source": "sky", "set": {"sun": 9}}]})",
                     "sun");
}

// Switching what lights the scene: the new map, how bright and turned carries over, the diff
// asks for a new upload, and the inverse puts the exact previous map back.
TEST(Edits, EnvironmentSwitchAndItsUndo) {
  const Scene studio = load_scene(test::asset("furnace_sphere.gltf"), {.environment = "studio"});
  Scene scene = studio;
  apply_edit(scene, EnvironmentEdit{.intensity = 2.0f});
  EXPECT_FALSE(diff_scenes(studio, scene).environment_map);  // same map, brighter
  const Scene bright = scene;

  const EnvironmentEdit to_sky{.source = std::filesystem::path("sky"),
                               .sun_elevation_degrees = 20.0f};
  const Edit undo_sky = inverse_edit(scene, to_sky);
  apply_edit(scene, to_sky);
  ASSERT_TRUE(scene.environment);
  EXPECT_EQ(scene.environment->path, "sky");
  EXPECT_EQ(scene.environment->sky.sun_elevation_degrees, 20.0f);
  EXPECT_EQ(scene.environment->sky.turbidity, SkyParameters{}.turbidity);
  EXPECT_EQ(scene.environment->intensity, 2.0f);
  ChangeSet changes = diff_scenes(bright, scene);
  EXPECT_TRUE(changes.environment_map && changes.environment && changes.light_tables);

  // The sun alone re-makes the sky, keeping what it does not set.
  const Scene first_sky = scene;
  const EnvironmentEdit sun{.sun_azimuth_degrees = 120.0f};
  const Edit undo_sun = inverse_edit(scene, sun);
  apply_edit(scene, sun);
  EXPECT_EQ(scene.environment->sky.sun_elevation_degrees, 20.0f);
  EXPECT_EQ(scene.environment->sky.sun_azimuth_degrees, 120.0f);
  EXPECT_NE(scene.environment->texels, first_sky.environment->texels);
  EXPECT_TRUE(diff_scenes(first_sky, scene).environment_map);
  apply_edit(scene, undo_sun);
  EXPECT_EQ(scene.environment->texels, first_sky.environment->texels);
  EXPECT_TRUE(diff_scenes(first_sky, scene).empty());

  const EnvironmentEdit off{.source = std::filesystem::path("none")};
  const Edit undo_off = inverse_edit(scene, off);
  apply_edit(scene, off);
  EXPECT_FALSE(scene.environment.has_value());
  EXPECT_TRUE(diff_scenes(first_sky, scene).environment_map);
  apply_edit(scene, undo_off);
  EXPECT_TRUE(diff_scenes(first_sky, scene).empty());

  apply_edit(scene, undo_sky);
  EXPECT_EQ(scene.environment->path, "studio");
  EXPECT_EQ(scene.environment->texels, studio.environment->texels);
  EXPECT_EQ(scene.environment->intensity, 2.0f);
  EXPECT_TRUE(diff_scenes(bright, scene).empty());
}

TEST(Edits, EnvironmentEditsRefusedLeaveTheSceneAsItWas) {
  Scene scene = load_scene(test::asset("furnace_sphere.gltf"), {.environment = "studio"});
  const Scene before = scene;
  const EnvironmentEdit sun{.turbidity = 5.0f};  // the studio has no sun
  EXPECT_THROW(inverse_edit(scene, sun), InputError);
  EXPECT_THROW(apply_edit(scene, sun), InputError);
  const EnvironmentEdit murky{.source = std::filesystem::path("sky"), .turbidity = 20.0f};
  EXPECT_THROW(inverse_edit(scene, murky), InputError);
  EXPECT_THROW(apply_edit(scene, murky), InputError);
  EXPECT_THROW(apply_edit(scene, EnvironmentEdit{.source = test::temp_dir("env") / "missing.hdr"}),
               InputError);
  EXPECT_TRUE(diff_scenes(before, scene).empty());
  EXPECT_EQ(scene.environment->texels, before.environment->texels);
  // Without an environment there is nothing to brighten, but one can be switched on.
  Scene dark = cornell();
  EXPECT_THROW(apply_edit(dark, EnvironmentEdit{.intensity = 2.0f}), InputError);
  apply_edit(dark, EnvironmentEdit{.source = std::filesystem::path("studio"), .intensity = 0.5f});
  ASSERT_TRUE(dark.environment);
  EXPECT_EQ(dark.environment->intensity, 0.5f);
}

// Every kind of edit followed by its inverse leaves the scene exactly as it was.
TEST(Edits, InverseRestoresTheSceneExactly) {
  const Scene base = load_scene(test::asset("cornell_sphere.glb"));
  Scene with_sky = base;
  with_sky.environment = test::uniform_environment(1.0f);
  const Edit edits[] = {
      TransformEdit{"sphere", glm::vec3(0.1f, -0.02f, 0.3f), std::nullopt},
      TransformEdit{"sphere", std::nullopt, glm::scale(glm::mat4(1.0f), glm::vec3(2.0f))},
      MaterialEdit{"white", {{"specular_roughness", {0.3f}}, {"base_color", {0.1f, 0.2f, 0.3f}}}},
      MaterialEdit{"white", {{"specular_roughness", {0.3f}}, {"specular_roughness", {0.7f}}}},
      LightEdit{"lamp", 7.0f, glm::vec3(0.1f, 0.2f, 0.3f), 4.0f},
      VisibilityEdit{"sphere", false},
      CameraEdit{glm::vec3(0.0f, 0.1f, -0.2f), std::nullopt},
      EnvironmentEdit{.intensity = 0.25f, .rotation = 1.5f},
  };
  for (const Edit& edit : edits) {
    Scene scene = with_sky;
    const Edit inverse = inverse_edit(scene, edit);
    apply_edit(scene, edit);
    EXPECT_FALSE(diff_scenes(with_sky, scene).empty()) << describe(edit);
    apply_edit(scene, inverse);
    EXPECT_TRUE(diff_scenes(with_sky, scene).empty()) << describe(edit);
    for (size_t n = 0; n < with_sky.nodes.size(); ++n) {
      EXPECT_EQ(scene.nodes[n].local, with_sky.nodes[n].local) << describe(edit);
      EXPECT_EQ(scene.nodes[n].visible, with_sky.nodes[n].visible) << describe(edit);
    }
    for (size_t m = 0; m < with_sky.materials.size(); ++m)
      EXPECT_EQ(std::memcmp(&scene.materials[m].params, &with_sky.materials[m].params,
                            sizeof(MaterialParameters)),
                0)
          << describe(edit);
    for (size_t l = 0; l < with_sky.lights.size(); ++l) {
      EXPECT_EQ(scene.lights[l].intensity, with_sky.lights[l].intensity);
      EXPECT_EQ(scene.lights[l].color, with_sky.lights[l].color);
      EXPECT_EQ(scene.lights[l].range, with_sky.lights[l].range);
    }
    EXPECT_EQ(scene.environment->intensity, with_sky.environment->intensity);
    EXPECT_EQ(scene.environment->rotation, with_sky.environment->rotation);
  }
}

TEST(Edits, InverseRefusesWhatApplyRefuses) {
  const Scene scene = cornell();
  EXPECT_THROW(inverse_edit(scene, TransformEdit{"teapot", glm::vec3(0.0f), std::nullopt}),
               InputError);
  EXPECT_THROW(inverse_edit(scene, MaterialEdit{"red", {{"base_color", {1.0f}}}}), InputError);
  EXPECT_THROW(inverse_edit(scene, MaterialEdit{"red", {{"colour", {1.0f, 0.0f, 0.0f}}}}),
               InputError);
  EXPECT_THROW(inverse_edit(scene, LightEdit{"tall_block", 1.0f, std::nullopt, std::nullopt}),
               InputError);
  EXPECT_THROW(inverse_edit(scene, EnvironmentEdit{.intensity = 1.0f}), InputError);
}

}  // namespace
}  // namespace hipr
