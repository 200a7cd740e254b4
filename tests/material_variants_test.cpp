// KHR_materials_variants: the file's variants are listed, one is shown by name or index (a load
// option, an edit and its undo), bad mappings are one-line errors, and a switch is a change of
// the primitives it remaps (scene_diff), which the renderer takes like a fresh upload.
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "material_variants_support.h"
#include "test_support.h"

namespace hipr {
namespace {
namespace fs = std::filesystem;
using json = nlohmann::json;

uint32_t material_of(const Scene& scene, const std::string& mesh) {
  for (const Mesh& m : scene.meshes)
    if (m.name == mesh) return m.primitives.at(0).material;
  ADD_FAILURE() << "no mesh " << mesh;
  return 0;
}

std::string material_name(const Scene& scene, const std::string& mesh) {
  return scene.materials[material_of(scene, mesh)].name;
}

TEST(MaterialVariants, LoadedAndShownByNameOrIndex) {
  const fs::path file = test::cornell_box_with_variants(test::temp_dir("variants"));
  const Scene plain = load_scene(file);
  EXPECT_EQ(plain.material_variants, (std::vector<std::string>{"warm", "lamp"}));
  EXPECT_EQ(plain.active_variant, -1);
  EXPECT_EQ(material_name(plain, "tall_block"), "white");
  EXPECT_EQ(material_name(plain, "short_block"), "white");

  SceneLoadOptions options;
  options.variant = "warm";
  const Scene warm = load_scene(file, options);
  EXPECT_EQ(warm.active_variant, 0);
  EXPECT_EQ(material_name(warm, "tall_block"), "red");
  EXPECT_EQ(material_name(warm, "short_block"), "green");
  EXPECT_EQ(material_name(warm, "floor"), "white");  // not mapped: its default

  options.variant = "1";
  const Scene lamp = load_scene(file, options);
  EXPECT_EQ(lamp.active_variant, 1);
  EXPECT_EQ(material_name(lamp, "tall_block"), "light");
  EXPECT_EQ(material_name(lamp, "short_block"), "white");

  options.variant = "cold";
  try {
    load_scene(file, options);
    ADD_FAILURE() << "an unknown variant loaded";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("0 'warm', 1 'lamp'"), std::string::npos) << e.what();
  }
}

TEST(MaterialVariants, AnEditAndItsUndoSwitchTheMaterials) {
  Scene scene = load_scene(test::cornell_box_with_variants(test::temp_dir("variants_edit")));
  const Edit edit =
      parse_edit_script(R"({"edits": [{"op": "variant", "name": "lamp"}]})", "script").at(0);
  const Edit undo = inverse_edit(scene, edit);
  const ChangeSet changes = test::edit_scene(scene, edit);
  EXPECT_EQ(material_name(scene, "tall_block"), "light");
  EXPECT_TRUE(changes.geometry);
  EXPECT_TRUE(changes.light_tables);        // the block became an emitter
  EXPECT_EQ(changes.instances.size(), 1u);  // the tall block; the short one is not remapped
  EXPECT_EQ(describe(edit), "variant lamp");
  test::edit_scene(scene, undo);
  EXPECT_EQ(scene.active_variant, -1);
  EXPECT_EQ(material_name(scene, "tall_block"), "white");
  EXPECT_THROW(apply_edit(scene, VariantEdit{"nope"}), InputError);
  EXPECT_EQ(scene.active_variant, -1);
}

TEST(MaterialVariants, BadMappingsAreOneLineErrors) {
  const fs::path dir = test::temp_dir("variants_bad");
  const fs::path good = test::cornell_box_with_variants(dir);
  json doc;
  std::ifstream(good) >> doc;
  const auto mappings = [](json& d) -> json& {
    return d["meshes"][6]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"];
  };
  std::vector<std::pair<std::string, json>> cases;
  json missing_material = doc;
  mappings(missing_material)[0]["material"] = 42;
  cases.push_back({"missing material", missing_material});
  json missing_variant = doc;
  mappings(missing_variant)[0]["variants"] = {7};
  cases.push_back({"missing variant", missing_variant});
  json not_an_array = doc;
  mappings(not_an_array) = "red";
  cases.push_back({"mappings not an array", not_an_array});
  json no_names = doc;
  no_names["extensions"]["KHR_materials_variants"].erase("variants");
  cases.push_back({"no variants", no_names});
  for (const auto& [name, spoiled] : cases) {
    const fs::path path = dir / "bad.gltf";
    std::ofstream(path) << spoiled.dump();
    try {
      load_scene(path);
      ADD_FAILURE() << name << ": loaded";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("variant"), std::string::npos)
          << name << ": " << e.what();
      EXPECT_EQ(std::string(e.what()).find('\n'), std::string::npos) << name;
    }
  }
}

}  // namespace
}  // namespace hipr
