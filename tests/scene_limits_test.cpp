// What a scene may hold (scene/scene_limits.h, README "Limits"): transforms whose world-space
// quantities overflow are refused where the scene is loaded or edited, an edit that would make
// one leaves the scene as it was, and a file's counts are bounded before anything is allocated.
#include <glm/gtc/matrix_transform.hpp>

#include <cstring>
#include <limits>

#include "core/error.h"
#include "gltf_document.h"
#include "hipr/edits.h"
#include "hipr/scene_loader.h"
#include "scene/default_camera.h"
#include "scene/gltf_accessors.h"
#include "scene/scene_limits.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;

// The loader's one-line refusal of `doc`, containing `needle`.
void expect_refused(const test::Document& doc, const std::string& needle) {
  const fs::path file = test::temp_dir("scene_limits") / "refused.gltf";
  test::write_document(file, doc);
  try {
    load_scene(file);
    ADD_FAILURE() << "loaded, expected: " << needle;
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << "one line";
  }
}

test::Document with_node_matrix(const std::vector<double>& matrix) {
  test::Document doc = test::triangle_document();
  doc.gltf["nodes"][0]["matrix"] = matrix;
  return doc;
}

TEST(SceneLimits, TransformsThatOverflowAreRefusedAtLoad) {
  // Finite numbers, so the loader's finiteness check let them through; their bounds overflow.
  expect_refused(with_node_matrix({3e38, 0, 0, 0, 0, 3e38, 0, 0, 0, 0, 3e38, 0, 3e38, 0, 0, 1}),
                 "out of range");
  expect_refused(with_node_matrix({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 2e9, 0, 0, 1}),
                 "out of range");
  // Far, but within the range: loads.
  const fs::path file = test::temp_dir("scene_limits_far") / "far.gltf";
  test::write_document(file, with_node_matrix({1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 1e8, 0, 0, 1}));
  EXPECT_NO_THROW(load_scene(file));
}

// Each refused edit throws one line and the scene is the one before it, field for field.
void expect_edit_refused(Scene& scene, const Edit& edit) {
  const Scene before = scene;
  EXPECT_THROW(apply_edit(scene, edit), InputError) << describe(edit);
  ASSERT_EQ(scene.nodes.size(), before.nodes.size()) << describe(edit);
  for (size_t n = 0; n < scene.nodes.size(); ++n)
    EXPECT_EQ(scene.nodes[n].local, before.nodes[n].local) << describe(edit);
  EXPECT_EQ(scene.root_nodes, before.root_nodes) << describe(edit);
  EXPECT_EQ(scene.cameras.size(), before.cameras.size()) << describe(edit);
  EXPECT_EQ(scene.meshes.size(), before.meshes.size()) << describe(edit);
  for (size_t m = 0; m < scene.meshes.size(); ++m)
    for (size_t p = 0; p < scene.meshes[m].primitives.size(); ++p)
      EXPECT_EQ(scene.meshes[m].primitives[p].positions, before.meshes[m].primitives[p].positions)
          << describe(edit);
  EXPECT_EQ(scene.lights, before.lights) << describe(edit);
  EXPECT_EQ(resolve_camera(scene).camera_to_world, resolve_camera(before).camera_to_world)
      << describe(edit);
}

TEST(SceneLimits, AnEditBeyondTheRangeLeavesTheSceneAsItWas) {
  Scene scene = load_scene(test::asset("cornell_box.gltf"));
  expect_edit_refused(scene,
                      TransformEdit{"tall_block", glm::vec3(3e38f, 0.0f, 0.0f), std::nullopt});
  // Two moves that are each in range but add up beyond it: the second is refused.
  apply_edit(scene, TransformEdit{"tall_block", glm::vec3(6e8f, 0.0f, 0.0f), std::nullopt});
  expect_edit_refused(scene,
                      TransformEdit{"tall_block", glm::vec3(6e8f, 0.0f, 0.0f), std::nullopt});
  expect_edit_refused(scene, TransformEdit{"short_block", std::nullopt,
                                           glm::scale(glm::mat4(1.0f), glm::vec3(1e30f))});
  expect_edit_refused(scene, DuplicateEdit{"short_block", "far", glm::vec3(0.0f, 3e38f, 0.0f)});
  expect_edit_refused(
      scene, DeformEdit{"short_block", glm::scale(glm::mat4(1.0f), glm::vec3(1e36f)), nullptr});
  expect_edit_refused(scene, CameraEdit{glm::vec3(0.0f, 0.0f, 3e38f), std::nullopt});
  expect_edit_refused(scene, CameraEdit{std::nullopt, glm::mat4(0.0f)});  // no frame at all
  expect_edit_refused(scene, MaterialEdit{"light", {{"emission_luminance", {1e13f}}}});
  // Out of a parameter's range or NaN (the viewer's edits are made in code, not parsed): refused
  // before any value is written.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const MaterialParameters white = scene.materials[0].params;
  expect_edit_refused(
      scene,
      MaterialEdit{"white", {{"specular_roughness", {0.5f}}, {"base_color", {nan, 0.5f, 0.5f}}}});
  expect_edit_refused(scene, MaterialEdit{"white", {{"base_color", {2.0f, 0.5f, 0.5f}}}});
  EXPECT_EQ(scene.materials[0].params.specular_roughness, white.specular_roughness);

  // Without a camera a camera edit first pins the default view as a node: a refused one does not.
  const fs::path dir = test::temp_dir("scene_limits_camera");
  Scene camera_less = load_scene(test::camera_less_cornell_box(dir));
  expect_edit_refused(camera_less, CameraEdit{glm::vec3(3e38f, 0.0f, 0.0f), std::nullopt});
  EXPECT_LT(camera_less.camera_node(), 0);

  Scene lamp = load_scene(test::asset("cornell_sphere.glb"));
  ASSERT_FALSE(lamp.light_nodes().empty());
  const std::string light = lamp.nodes[lamp.light_nodes().front()].name;
  expect_edit_refused(lamp, LightEdit{light, 1e13f, std::nullopt, std::nullopt});
  expect_edit_refused(lamp,
                      LightEdit{light, std::nullopt, glm::vec3(nan, 1.0f, 1.0f), std::nullopt});
  expect_edit_refused(lamp, LightEdit{light, std::nullopt, std::nullopt, -1.0f});
  expect_edit_refused(lamp, TransformEdit{light, glm::vec3(0.0f, -2e9f, 0.0f), std::nullopt});
}

TEST(GltfLimits, AnAccessorWithoutDataIsBounded) {
  test::Document doc = test::triangle_document();
  doc.gltf["accessors"].push_back(
      {{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", 2000000000}});
  expect_refused(doc, "no bufferView");
  test::Document small = test::triangle_document();
  small.gltf["accessors"].push_back(
      {{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", 1000}});
  const fs::path file = test::temp_dir("gltf_limits_small") / "small.gltf";
  test::write_document(file, small);
  EXPECT_NO_THROW(load_scene(file)) << "a small one is all zeros, per the spec";
}

TEST(GltfLimits, SparseCountsStayWithinTheirAccessorAndViews) {
  test::Document doc = test::triangle_document();
  const int indices =
      doc.add_accessor(std::vector<uint16_t>{0, 1}, test::kUnsignedShort, "SCALAR", 2);
  const int values =
      doc.add_accessor(std::vector<float>{1, 1, 1, 2, 2, 2}, test::kFloat, "VEC3", 2);
  const auto view_of = [&](int accessor) {
    return doc.gltf["accessors"][size_t(accessor)]["bufferView"];
  };
  nlohmann::json sparse = {
      {"count", 2},
      {"indices", {{"bufferView", view_of(indices)}, {"componentType", test::kUnsignedShort}}},
      {"values", {{"bufferView", view_of(values)}}}};
  test::Document more = doc;
  more.gltf["accessors"].push_back(
      {{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", 1}, {"sparse", sparse}});
  expect_refused(more, "replaces more elements");
  test::Document past = doc;
  sparse["count"] = 1000;
  past.gltf["accessors"].push_back(
      {{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", 5000}, {"sparse", sparse}});
  expect_refused(past, "past the end");
}

TEST(GltfLimits, PrimitivesSharingAnAccessorAddUpBeforeAnyIsRead) {
  test::Document doc = test::triangle_document();
  const size_t count = gltf::kMaxZeroFilledElements;  // allowed alone: all zeros
  doc.gltf["accessors"].push_back(
      {{"componentType", test::kFloat}, {"type", "VEC3"}, {"count", count}});
  const int shared = int(doc.gltf["accessors"].size() - 1);
  nlohmann::json primitives = nlohmann::json::array();
  // Each makes count vertices and count indices: one more than the scene's budget holds.
  for (size_t k = 0; k <= gltf::kMaxSceneElements / (2 * count); ++k)
    primitives.push_back({{"attributes", {{"POSITION", shared}}}});
  doc.gltf["meshes"].push_back({{"name", "many"}, {"primitives", primitives}});
  expect_refused(doc, "vertices and indices in all");
}

// PNGs whose headers say 20000 x 1 (a side beyond the limit) and 16384 x 8192 (pixels beyond
// it; stb itself would decode both): refused from the header, before a pixel is decoded (the
// image falls back, with a warning, as a broken one does).
TEST(GltfLimits, AnImageBeyondTheLimitsIsNotDecoded) {
  for (const auto& [width, height] : {std::pair{20000u, 1u}, std::pair{16384u, 8192u}}) {
    std::vector<unsigned char> png = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n',
                                      0,    0,   0,   13,  'I',  'H',  'D',  'R'};
    for (const uint32_t side : {width, height})
      for (int shift = 24; shift >= 0; shift -= 8) png.push_back((unsigned char)(side >> shift));
    for (const unsigned char b : {8, 6, 0, 0, 0, 0, 0, 0, 0})
      png.push_back(b);  // RGBA8, then a CRC
    test::Document doc = test::triangle_document();
    const size_t offset = doc.bin.size();
    doc.bin.insert(doc.bin.end(), png.begin(), png.end());
    doc.bin.resize((doc.bin.size() + 3) / 4 * 4, 0);
    doc.gltf["bufferViews"].push_back(
        {{"buffer", 0}, {"byteOffset", offset}, {"byteLength", png.size()}});
    doc.gltf["images"] = {
        {{"bufferView", doc.gltf["bufferViews"].size() - 1}, {"mimeType", "image/png"}}};
    doc.gltf["textures"] = {{{"source", 0}}};
    doc.gltf["materials"][0]["pbrMetallicRoughness"] = {{"baseColorTexture", {{"index", 0}}}};
    const fs::path file = test::temp_dir("gltf_limits_image") / "image.gltf";
    test::write_document(file, doc);
    const Scene scene = load_scene(file);
    for (const Image& image : scene.images) EXPECT_NE(image.width, width) << width << "x" << height;
  }
}

}  // namespace
}  // namespace hipr
