// save_scene: an edited scene saved as glTF loads back as the same scene (every edit kind,
// .gltf and .glb, in place and elsewhere), an unedited one as the same document, and bad
// output paths fail cleanly with nothing left behind. Also the loader's side of it:
// KHR_node_visibility and the hipr extras, validated.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <limits>

#include <unistd.h>

#include <glm/gtc/matrix_transform.hpp>

#include "core/error.h"
#include "core/file_util.h"
#include "gltf_document.h"
#include "hipr/edits.h"
#include "hipr/renderer.h"
#include "hipr/scene_loader.h"
#include "hipr/scene_writer.h"
#include "scene_writer_support.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using nlohmann::json;
using test::expect_same_scene;

json read_json(const fs::path& file) {
  std::ifstream in(file);
  return json::parse(in);
}

// The document with its keys in file order (json sorts them): equal texts, same key order.
std::string ordered_text(const fs::path& file) {
  std::ifstream in(file);
  return nlohmann::ordered_json::parse(in).dump();
}

// The JSON chunk (parsed) and BIN chunk of a .glb.
std::pair<json, std::vector<unsigned char>> glb_chunks(const fs::path& file) {
  const std::vector<unsigned char> bytes = read_file_bytes(file);
  uint32_t json_length = 0, bin_length = 0;
  std::memcpy(&json_length, bytes.data() + 12, 4);
  const auto json_begin = bytes.begin() + 20;
  json doc = json::parse(json_begin, json_begin + json_length);
  std::vector<unsigned char> bin;
  if (20 + json_length + 8 <= bytes.size()) {
    std::memcpy(&bin_length, bytes.data() + 20 + json_length, 4);
    bin.assign(json_begin + json_length + 8, json_begin + json_length + 8 + bin_length);
  }
  return {doc, bin};
}

std::vector<std::string> folder_listing(const fs::path& folder) {
  std::vector<std::string> names;
  for (const auto& entry : fs::recursive_directory_iterator(folder))
    names.push_back(entry.path().lexically_relative(folder).string());
  std::sort(names.begin(), names.end());
  return names;
}

// Applies `edits` to (a copy of) `loaded`, saves to `out`, reloads: the reloaded scene must
// equal the edited one.
Scene round_trip(const Scene& loaded, const std::vector<Edit>& edits, const fs::path& out) {
  Scene scene = loaded;
  for (const Edit& edit : edits) apply_edit(scene, edit);
  save_scene(scene, out);
  Scene reloaded = load_scene(out);
  expect_same_scene(scene, reloaded, false);
  return reloaded;
}

Scene round_trip(const fs::path& source, const std::vector<Edit>& edits, const fs::path& out) {
  return round_trip(load_scene(source), edits, out);
}

// Every edit kind on the shipped Cornell box: a TRS node moved, one set by matrix, one hidden,
// the camera moved, a material given every OpenPBR parameter, the emitter brightened beyond
// glTF's [0, 1] emissive range.
std::vector<Edit> cornell_box_edits() {
  glm::mat4 matrix = glm::translate(glm::mat4(1.0f), glm::vec3(0.3f, 0.01f, 0.2f)) *
                     glm::rotate(glm::mat4(1.0f), 0.4f, glm::vec3(0, 1, 0)) *
                     glm::scale(glm::mat4(1.0f), glm::vec3(0.9f));
  return {
      TransformEdit{"tall_block", glm::vec3(0.06f, 0.0f, -0.08f), std::nullopt},
      TransformEdit{"short_block", std::nullopt, matrix},
      VisibilityEdit{"back_wall", false},
      CameraEdit{glm::vec3(0.0f, 0.02f, -0.1f), std::nullopt},
      test::every_parameter_edit("white", 1),
      MaterialEdit{"red", {{"base_color", {0.05f, 0.1f, 0.65f}}, {"specular_roughness", {0.25f}}}},
      MaterialEdit{
          "green",
          {{"specular_roughness", {0.5f}}, {"base_metalness", {0.3f}}, {"specular_ior", {1.7f}}}},
      MaterialEdit{"light",
                   {{"emission_luminance", {30.0f}}, {"emission_color", {2.0f, 1.0f, 0.5f}}}}};
}

TEST(SceneWriter, GltfIntoAnotherFolderRoundTripsEveryEditKind) {
  const fs::path dir = test::temp_dir("writer-gltf");
  round_trip(test::asset("cornell_box.gltf"), cornell_box_edits(), dir / "edited.gltf");
  // The buffer was copied beside it; no temporary file is left.
  EXPECT_EQ(folder_listing(dir), (std::vector<std::string>{"cornell_box.bin", "edited.gltf"}));
  EXPECT_EQ(read_file_bytes(dir / "cornell_box.bin"),
            read_file_bytes(test::asset("cornell_box.bin")));

  const json doc = read_json(dir / "edited.gltf");
  const auto node = [&](const std::string& name) {
    for (const json& n : doc["nodes"])
      if (n.value("name", "") == name) return n;
    return json();
  };
  // A translation keeps TRS form; a matrix edit writes a matrix.
  EXPECT_TRUE(node("tall_block").contains("translation"));
  EXPECT_TRUE(node("tall_block").contains("rotation"));
  EXPECT_FALSE(node("tall_block").contains("matrix"));
  EXPECT_TRUE(node("short_block").contains("matrix"));
  EXPECT_FALSE(node("short_block").contains("translation"));
  EXPECT_EQ(node("back_wall")["extensions"]["KHR_node_visibility"]["visible"], false);
  EXPECT_FALSE(node("floor").contains("extensions"));
  const auto used = doc["extensionsUsed"].get<std::vector<std::string>>();
  for (const char* e : {"KHR_node_visibility", "KHR_materials_clearcoat", "KHR_materials_sheen",
                        "KHR_materials_iridescence"})
    EXPECT_NE(std::find(used.begin(), used.end(), e), used.end()) << e;

  // Values glTF can hold go to glTF (and only there); the rest to extras.hipr_openpbr.
  const json& red = doc["materials"][1];
  EXPECT_FLOAT_EQ(red["pbrMetallicRoughness"]["baseColorFactor"][2].get<float>(), 0.65f);
  EXPECT_FLOAT_EQ(red["pbrMetallicRoughness"]["roughnessFactor"].get<float>(), 0.25f);
  // Only one extra: glTF tints thin-walled transmission by the base colour, the edit did not.
  EXPECT_EQ(red["extras"]["hipr_openpbr"].size(), 1u);
  EXPECT_TRUE(red["extras"]["hipr_openpbr"].contains("transmission_color"));
  const json& green = doc["materials"][2];
  EXPECT_FALSE(green.contains("extras"));
  EXPECT_EQ(green["extensions"]["KHR_materials_ior"]["ior"], 1.7);
  const json& white = doc["materials"][0]["extras"]["hipr_openpbr"];
  EXPECT_TRUE(white.contains("coat_darkening"));
  EXPECT_TRUE(white.contains("base_diffuse_roughness"));
  EXPECT_TRUE(white.contains("subsurface_radius"));
  EXPECT_FALSE(white.contains("base_color"));
  EXPECT_FALSE(white.contains("specular_roughness"));
  EXPECT_TRUE(doc["materials"][0]["extensions"].contains("KHR_materials_clearcoat"));
  // Emission above glTF's range: the glTF fields give the same light, the extras the exact split.
  const json& light = doc["materials"][3];
  EXPECT_FLOAT_EQ(light["emissiveFactor"][0].get<float>(), 1.0f);
  EXPECT_FLOAT_EQ(
      light["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"].get<float>(),
      60.0f);
  EXPECT_EQ(light["extras"]["hipr_openpbr"]["emission_color"][0], 2.0);
}

TEST(SceneWriter, GlbRoundTripsEveryEditKindInOneFile) {
  const fs::path dir = test::temp_dir("writer-glb");
  round_trip(test::asset("cornell_box.gltf"), cornell_box_edits(), dir / "edited.glb");
  EXPECT_EQ(folder_listing(dir), std::vector<std::string>{"edited.glb"});
  // And back from .glb to .gltf: the BIN chunk becomes <name>.bin.
  round_trip(dir / "edited.glb",
             {TransformEdit{"floor", glm::vec3(0.0f, -0.01f, 0.0f), std::nullopt}},
             dir / "again.gltf");
  EXPECT_TRUE(fs::exists(dir / "again.bin"));
}

TEST(SceneWriter, LightEditsRoundTrip) {
  const fs::path dir = test::temp_dir("writer-light");
  const std::vector<Edit> edits = {
      LightEdit{"lamp", 3.0f, glm::vec3(1.0f, 0.9f, 0.8f), 2.5f},
      TransformEdit{"sphere", glm::vec3(-0.1f, 0.0f, 0.05f), std::nullopt}};
  round_trip(test::asset("cornell_sphere.glb"), edits, dir / "a.glb");
  round_trip(test::asset("cornell_sphere.glb"), edits, dir / "a.gltf");
  // A colour above glTF's [0, 1]: written as colour / peak and intensity x peak, exact in extras.
  const std::vector<Edit> bright = {
      LightEdit{"lamp", 2.0f, glm::vec3(4.0f, 2.0f, 1.0f), std::nullopt}};
  round_trip(test::asset("cornell_sphere.glb"), bright, dir / "b.gltf");
  const json light = read_json(dir / "b.gltf")["extensions"]["KHR_lights_punctual"]["lights"][0];
  EXPECT_FLOAT_EQ(light["color"][0].get<float>(), 1.0f);
  EXPECT_FLOAT_EQ(light["intensity"].get<float>(), 8.0f);
  EXPECT_EQ(light["extras"]["hipr_light"]["intensity"], 2.0);
  // Range back to infinite (0) removes it.
  Scene scene = load_scene(dir / "a.gltf");
  apply_edit(scene, LightEdit{"lamp", std::nullopt, std::nullopt, 0.0f});
  save_scene(scene, dir / "c.gltf");
  EXPECT_FALSE(read_json(dir / "c.gltf")["extensions"]["KHR_lights_punctual"]["lights"][0].contains(
      "range"));
  expect_same_scene(scene, load_scene(dir / "c.gltf"), false);
}

TEST(SceneWriter, SavingInPlaceIsAtomicAndKeepsSideFiles) {
  const fs::path dir = test::temp_dir("writer-in-place");
  fs::copy(test::asset("cornell_box.gltf"), dir / "box.gltf");
  fs::copy(test::asset("cornell_box.bin"), dir / "cornell_box.bin");
  round_trip(dir / "box.gltf", cornell_box_edits(), dir / "box.gltf");
  EXPECT_EQ(folder_listing(dir), (std::vector<std::string>{"box.gltf", "cornell_box.bin"}));
  EXPECT_EQ(read_file_bytes(dir / "cornell_box.bin"),
            read_file_bytes(test::asset("cornell_box.bin")));
  // A second save of the saved file changes nothing: the extras are recomputed, not stacked.
  const std::vector<unsigned char> first = read_file_bytes(dir / "box.gltf");
  save_scene(load_scene(dir / "box.gltf"), dir / "box.gltf");
  EXPECT_EQ(read_file_bytes(dir / "box.gltf"), first);

  fs::copy(test::asset("cornell_sphere.glb"), dir / "sphere.glb");
  round_trip(dir / "sphere.glb",
             {VisibilityEdit{"sphere", false}, LightEdit{"lamp", 1.0f, std::nullopt, std::nullopt}},
             dir / "sphere.glb");
}

TEST(SceneWriter, UneditedSceneSavesAsTheSameDocument) {
  const fs::path dir = test::temp_dir("writer-unedited");
  for (const char* name : {"cornell_box.gltf", "furnace_sphere.gltf"}) {
    const Scene scene = load_scene(test::asset(name));
    save_scene(scene, dir / name);
    // Same JSON (key order and all), and the same scene down to the content hash's inputs.
    EXPECT_EQ(ordered_text(dir / name), ordered_text(test::asset(name))) << name;
    const Scene reloaded = load_scene(dir / name);
    expect_same_scene(scene, reloaded, true);
    EXPECT_EQ(reloaded.content_hash, scene.content_hash) << name;
  }
  // A .gltf whose buffer is a data: URI, into a .glb.
  const Scene furnace = load_scene(test::asset("furnace_sphere.gltf"));
  save_scene(furnace, dir / "furnace.glb");
  expect_same_scene(furnace, load_scene(dir / "furnace.glb"), true);

  const Scene sphere = load_scene(test::asset("cornell_sphere.glb"));
  save_scene(sphere, dir / "sphere.glb");
  EXPECT_EQ(glb_chunks(dir / "sphere.glb"), glb_chunks(test::asset("cornell_sphere.glb")));
  expect_same_scene(sphere, load_scene(dir / "sphere.glb"), true);
  save_scene(sphere, dir / "sphere.gltf");
  expect_same_scene(sphere, load_scene(dir / "sphere.gltf"), true);
  EXPECT_EQ(read_json(dir / "sphere.gltf").dump().find("hipr_"), std::string::npos);
}

TEST(SceneWriter, EveryParameterRoundTripsOnAMaterialWithEveryExtension) {
  // A thick, masked material with every extension the loader reads; then every editable
  // parameter set (twice: varied values, then all weights and colours at their minimum).
  test::Document doc = test::triangle_document();
  doc.gltf["materials"][0] = {
      {"name", "mat"},
      {"alphaMode", "MASK"},
      {"alphaCutoff", 0.3},
      {"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 0.4, 0.3, 0.8}}}},
      {"extensions",
       {{"KHR_materials_transmission", {{"transmissionFactor", 0.5}}},
        {"KHR_materials_volume", {{"thicknessFactor", 0.2}, {"attenuationDistance", 0.5}}},
        {"KHR_materials_clearcoat", {{"clearcoatFactor", 0.5}}},
        {"KHR_materials_sheen", {{"sheenColorFactor", {0.2, 0.2, 0.2}}}},
        {"KHR_materials_iridescence", {{"iridescenceFactor", 0.5}}},
        {"KHR_materials_anisotropy", {{"anisotropyStrength", 0.5}}},
        {"KHR_materials_diffuse_transmission", {{"diffuseTransmissionFactor", 0.1}}},
        {"KHR_materials_dispersion", {{"dispersion", 0.3}}},
        {"KHR_materials_ior", {{"ior", 1.3}}},
        {"KHR_materials_specular", {{"specularFactor", 0.7}}},
        {"KHR_materials_emissive_strength", {{"emissiveStrength", 2.0}}}}}};
  const fs::path dir = test::temp_dir("writer-every-parameter");
  test::write_document(dir / "source.gltf", doc);
  for (int variant : {1, 2, 0}) {
    const std::string out = "saved" + std::to_string(variant);
    round_trip(dir / "source.gltf", {test::every_parameter_edit("mat", variant)},
               dir / (out + ".gltf"));
    round_trip(dir / "source.gltf", {test::every_parameter_edit("mat", variant)},
               dir / (out + ".glb"));
  }
  // glTF's default material (primitives without one) is editable too: kept in the document's
  // extras.
  doc.primitive().erase("material");
  test::write_document(dir / "no_material.gltf", doc);
  round_trip(dir / "no_material.gltf", {test::every_parameter_edit("default", 1)},
             dir / "no_material_saved.gltf");
}

// Dispersion edited on a thick glass: written as glTF's dispersion (20 / its Abbe number, so other
// viewers see the same glass) and declared; on a thin one, only in hipr's extras (glTF disperses
// only inside a volume).
TEST(SceneWriter, DispersionIsWrittenAsGltfsAbbeNumberInsideAVolume) {
  test::Document doc = test::triangle_document();
  doc.gltf["materials"][0] = {{"name", "glass"},
                              {"extensions",
                               {{"KHR_materials_transmission", {{"transmissionFactor", 1.0}}},
                                {"KHR_materials_volume", {{"thicknessFactor", 0.2}}}}}};
  doc.gltf["extensionsUsed"] = {"KHR_materials_transmission", "KHR_materials_volume"};
  const fs::path dir = test::temp_dir("writer-dispersion");
  test::write_document(dir / "thick.gltf", doc);
  const MaterialEdit edit{"glass",
                          {{"transmission_dispersion_scale", {0.5f}},
                           {"transmission_dispersion_abbe_number", {40.0f}}}};
  const Scene saved = round_trip(dir / "thick.gltf", {edit}, dir / "thick_saved.gltf");
  EXPECT_EQ(saved.materials[0].params.transmission_dispersion_scale, 0.5f);
  EXPECT_EQ(saved.materials[0].params.transmission_dispersion_abbe_number, 40.0f);
  const json written = read_json(dir / "thick_saved.gltf");
  EXPECT_EQ(written["materials"][0]["extensions"]["KHR_materials_dispersion"]["dispersion"], 0.25);
  const auto& used = written["extensionsUsed"];
  EXPECT_NE(std::find(used.begin(), used.end(), "KHR_materials_dispersion"), used.end());

  doc.gltf["materials"][0]["extensions"].erase("KHR_materials_volume");
  test::write_document(dir / "thin.gltf", doc);
  round_trip(dir / "thin.gltf", {edit}, dir / "thin_saved.gltf");
  const json thin = read_json(dir / "thin_saved.gltf");
  EXPECT_FALSE(thin["materials"][0]["extensions"].contains("KHR_materials_dispersion"));
}

TEST(SceneWriter, AnimatedNodesStayTrs) {
  // glTF forbids `matrix` on a node an animation targets: a matrix edit is decomposed into TRS.
  test::Document doc = test::triangle_document();
  const int times = doc.add_accessor(std::vector<float>{0.0f, 1.0f}, test::kFloat, "SCALAR", 2);
  const int moves = doc.add_accessor(std::vector<float>{0, 0, 0, 1, 0, 0}, test::kFloat, "VEC3", 2);
  doc.gltf["accessors"][size_t(times)]["min"] = {0.0};
  doc.gltf["accessors"][size_t(times)]["max"] = {1.0};
  doc.gltf["animations"] = json::array(
      {{{"channels", {{{"sampler", 0}, {"target", {{"node", 0}, {"path", "translation"}}}}}},
        {"samplers", {{{"input", times}, {"output", moves}}}}}});
  const fs::path dir = test::temp_dir("writer-animated");
  test::write_document(dir / "animated.gltf", doc);
  Scene scene = load_scene(dir / "animated.gltf");
  const glm::mat4 matrix = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f, -1.0f, 2.0f)) *
                           glm::rotate(glm::mat4(1.0f), 0.7f, glm::normalize(glm::vec3(1, 2, 3))) *
                           glm::scale(glm::mat4(1.0f), glm::vec3(2.0f, 0.5f, 1.5f));
  apply_edit(scene, TransformEdit{"tri", std::nullopt, matrix});
  save_scene(scene, dir / "saved.gltf");
  const json node = read_json(dir / "saved.gltf")["nodes"][0];
  EXPECT_FALSE(node.contains("matrix"));
  EXPECT_TRUE(node.contains("translation") && node.contains("rotation") && node.contains("scale"));
  const glm::mat4 loaded = load_scene(dir / "saved.gltf").nodes[0].local;
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) EXPECT_NEAR(loaded[c][r], matrix[c][r], 1e-5f) << c << "," << r;
}

TEST(SceneWriter, SharedScenesRoundTrip) {
  if (!test::shared_scenes_available()) GTEST_SKIP() << "shared scenes not present";
  const fs::path dir = test::temp_dir("writer-shared");
  for (const test::SharedScene& s : test::shared_scenes_to_save()) {
    SCOPED_TRACE(s.file);
    const fs::path source = test::shared_scene(s.file);
    Scene scene = load_scene(source);
    const std::vector<Edit> edits = test::typical_edits(scene);
    const fs::path folder = dir / fs::path(s.file).parent_path();
    fs::create_directories(folder);
    const std::string stem = fs::path(s.file).stem().string();
    round_trip(scene, edits, folder / (stem + ".gltf"));
    round_trip(scene, edits, folder / (stem + ".glb"));
    // Unedited, in the source's own container: the same scene and the same document (for a
    // .glb the same binary chunk too: nothing was decoded and re-encoded).
    const fs::path unedited = folder / (stem + "_unedited" + source.extension().string());
    save_scene(scene, unedited);
    expect_same_scene(scene, load_scene(unedited), true);
    if (source.extension() == ".gltf")
      EXPECT_EQ(ordered_text(unedited), ordered_text(source));
    else
      EXPECT_EQ(glb_chunks(unedited), glb_chunks(source));
  }
  // SheenChair's images were copied beside the .gltf under their own names (URIs with "./").
  EXPECT_TRUE(fs::exists(dir / "SheenChair" / "chair_fabric_albedo.png"));
  EXPECT_TRUE(fs::exists(dir / "LightsPunctualLamp" / "LightsPunctualLamp.data.bin"));
}

TEST(SceneWriter, BadOutputPathsFailWithNothingWritten) {
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  const fs::path dir = test::temp_dir("writer-bad");
  EXPECT_THROW(save_scene(scene, dir / "scene.obj"), InputError);
  EXPECT_THROW(save_scene(scene, dir / "scene"), InputError);
  EXPECT_THROW(save_scene(scene, dir / "missing" / "scene.gltf"), InputError);
  EXPECT_THROW(save_scene(scene, dir), InputError);
  fs::create_directories(dir / "folder.gltf");
  EXPECT_THROW(save_scene(scene, dir / "folder.gltf"), InputError);
  fs::remove(dir / "folder.gltf");
  EXPECT_TRUE(fs::is_empty(dir));
  // A folder no file can be created in (/proc refuses even root).
  EXPECT_THROW(save_scene(scene, "/proc/hipr-save-test.gltf"), InputError);
  EXPECT_THROW(save_scene(scene, "/proc/hipr-save-test.glb"), InputError);
  EXPECT_FALSE(fs::exists("/proc/hipr-save-test.gltf"));
  if (::geteuid() != 0) {
    const fs::path locked = dir / "locked";
    fs::create_directories(locked);
    fs::permissions(locked, fs::perms::owner_read | fs::perms::owner_exec);
    EXPECT_THROW(save_scene(scene, locked / "scene.glb"), InputError);
    EXPECT_THROW(save_scene(scene, locked / "scene.gltf"), InputError);
    fs::permissions(locked, fs::perms::owner_all);
    EXPECT_TRUE(fs::is_empty(locked));
  }
}

TEST(SceneWriter, RefusesToReplaceOtherFilesAndNeedsItsSource) {
  const fs::path dir = test::temp_dir("writer-refuse");
  const Scene scene = load_scene(test::asset("cornell_box.gltf"));
  // Another scene's buffer of the same name in the target folder is never replaced.
  test::write_bytes(dir / "cornell_box.bin", {1, 2, 3, 4});
  EXPECT_THROW(save_scene(scene, dir / "scene.gltf"), InputError);
  EXPECT_EQ(folder_listing(dir), std::vector<std::string>{"cornell_box.bin"});
  EXPECT_EQ(read_file_bytes(dir / "cornell_box.bin"), (std::vector<unsigned char>{1, 2, 3, 4}));
  // ... but an identical one (an earlier save) is simply reused.
  fs::copy(test::asset("cornell_box.bin"), dir / "cornell_box.bin",
           fs::copy_options::overwrite_existing);
  save_scene(scene, dir / "scene.gltf");
  expect_same_scene(scene, load_scene(dir / "scene.gltf"), true);

  // The source must still be there to supply meshes and buffers.
  const fs::path copy = dir / "copy";
  fs::create_directories(copy);
  fs::copy(test::asset("cornell_sphere.glb"), copy / "s.glb");
  const Scene sphere = load_scene(copy / "s.glb");
  fs::remove(copy / "s.glb");
  EXPECT_THROW(save_scene(sphere, copy / "s.glb"), InputError);
  EXPECT_TRUE(fs::is_empty(copy));
  // A value JSON cannot hold (only the API, not an edit script, can set it).
  Scene infinite = scene;
  infinite.materials[0].params.coat_darkening = std::numeric_limits<float>::infinity();
  EXPECT_THROW(save_scene(infinite, dir / "infinite.gltf"), InputError);
  EXPECT_FALSE(fs::exists(dir / "infinite.gltf"));
  // A scene built in code has no source at all.
  EXPECT_THROW(
      save_scene(test::make_furnace_scene(1.0f, glm::vec3(0.0f), 0.5f, 1.0f), dir / "furnace.gltf"),
      InputError);
  EXPECT_FALSE(fs::exists(dir / "furnace.gltf"));
}

// The loader's side: KHR_node_visibility and the extras, with bad values refused.
Scene load_document(const test::Document& doc, const std::string& name) {
  const fs::path dir = test::temp_dir("writer-loader-" + name);
  test::write_document(dir / "scene.gltf", doc);
  return load_scene(dir / "scene.gltf");
}

TEST(SceneWriterLoader, ReadsNodeVisibilityAndExtras) {
  test::Document doc = test::triangle_document();
  doc.gltf["nodes"][0]["extensions"]["KHR_node_visibility"]["visible"] = false;
  doc.gltf["extensionsRequired"] = {"KHR_node_visibility"};
  doc.gltf["extensionsUsed"] = {"KHR_node_visibility"};
  doc.gltf["materials"][0]["extras"] = {
      {"note", "kept"},
      {"hipr_openpbr", {{"coat_darkening", 0.25}, {"fuzz_color", {0.1, 0.2, 0.3}}}}};
  doc.gltf["extras"]["hipr_default_material"] = {{"base_weight", 0.5}};
  const Scene scene = load_document(doc, "good");
  EXPECT_FALSE(scene.nodes[0].visible);
  EXPECT_FALSE(scene.instances()[0].visible);
  EXPECT_FLOAT_EQ(scene.materials[0].params.coat_darkening, 0.25f);
  EXPECT_EQ(scene.materials[0].params.fuzz_color, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_FLOAT_EQ(scene.materials.back().params.base_weight, 0.5f);
}

TEST(SceneWriterLoader, BadExtrasAndVisibilityAreInputErrors) {
  const std::vector<std::pair<std::string, json>> bad_materials = {
      {"not_object", {{"hipr_openpbr", 3}}},
      {"unknown_key", {{"hipr_openpbr", {{"coat_sparkle", 1.0}}}}},
      {"string", {{"hipr_openpbr", {{"coat_darkening", "high"}}}}},
      {"out_of_range", {{"hipr_openpbr", {{"coat_darkening", 2.0}}}}},
      {"short_colour", {{"hipr_openpbr", {{"base_color", {0.5, 0.5}}}}}},
      {"colour_as_number", {{"hipr_openpbr", {{"base_color", 0.5}}}}},
      {"below_min", {{"hipr_openpbr", {{"specular_ior", 0.5}}}}},
  };
  for (const auto& [name, extras] : bad_materials) {
    test::Document doc = test::triangle_document();
    doc.gltf["materials"][0]["extras"] = extras;
    EXPECT_THROW(load_document(doc, name), InputError) << name;
  }
  test::Document visibility = test::triangle_document();
  visibility.gltf["nodes"][0]["extensions"]["KHR_node_visibility"]["visible"] = "no";
  EXPECT_THROW(load_document(visibility, "visibility"), InputError);
  test::Document root = test::triangle_document();
  root.gltf["extras"]["hipr_default_material"] = {{"base_weight", -1.0}};
  EXPECT_THROW(load_document(root, "default"), InputError);
  test::Document light = test::triangle_document();
  light.gltf["extensions"]["KHR_lights_punctual"]["lights"] = {
      {{"type", "point"}, {"extras", {{"hipr_light", {{"color", {1.0, -2.0, 1.0}}}}}}}};
  EXPECT_THROW(load_document(light, "light"), InputError);
  light.gltf["extensions"]["KHR_lights_punctual"]["lights"][0]["extras"]["hipr_light"] = {
      {"power", 1.0}};
  EXPECT_THROW(load_document(light, "light_key"), InputError);
}

TEST(SceneWriter, EditedAndSavedScenesRenderBitIdentical) {
  const fs::path dir = test::temp_dir("writer-render");
  Scene scene = load_scene(test::asset("cornell_sphere.glb"));
  const std::vector<Edit> edits = {
      TransformEdit{"sphere", glm::vec3(-0.05f, 0.0f, 0.05f), std::nullopt},
      VisibilityEdit{"tall_block", false},
      LightEdit{"lamp", 2.0f, glm::vec3(3.0f, 0.9f, 0.8f), 1.5f},
      MaterialEdit{"red",
                   {{"base_color", {0.1f, 0.6f, 0.2f}},
                    {"specular_roughness", {0.4f}},
                    {"base_diffuse_roughness", {0.7f}},
                    {"specular_weight", {1.0f}}}},
      MaterialEdit{"light", {{"emission_luminance", {25.0f}}}},
      CameraEdit{glm::vec3(0.01f, 0.0f, -0.05f), std::nullopt}};
  for (const Edit& edit : edits) apply_edit(scene, edit);
  save_scene(scene, dir / "edited.glb");
  const Scene reloaded = load_scene(dir / "edited.glb");
  RenderSettings settings;
  settings.width = 64;
  settings.height = 64;
  settings.seed = 7;
  settings.max_depth = 6;
  const ImageRGB a = test::render_finite(scene, settings, 4);
  const ImageRGB b = test::render_finite(reloaded, settings, 4);
  EXPECT_EQ(a.rgb, b.rgb);
  // The edits are visible (so the comparison means something).
  EXPECT_NE(test::render_finite(load_scene(test::asset("cornell_sphere.glb")), settings, 4).rgb,
            a.rgb);
}

}  // namespace
}  // namespace hipr
