#include "material_variants_support.h"

#include <fstream>
#include <nlohmann/json.hpp>

#include "test_support.h"

namespace hipr::test {

std::filesystem::path cornell_box_with_variants(const std::filesystem::path& dir) {
  nlohmann::json gltf;
  std::ifstream(asset("cornell_box.gltf")) >> gltf;
  // Materials: 0 white, 1 red, 2 green, 3 light. Meshes 5 and 6: short and tall block.
  gltf["extensionsUsed"].push_back("KHR_materials_variants");
  gltf["extensions"]["KHR_materials_variants"]["variants"] = {{{"name", "warm"}},
                                                              {{"name", "lamp"}}};
  const auto map = [&](int mesh, nlohmann::json mappings) {
    gltf["meshes"][mesh]["primitives"][0]["extensions"]["KHR_materials_variants"]["mappings"] =
        std::move(mappings);
  };
  map(6, {{{"material", 1}, {"variants", {0}}}, {{"material", 3}, {"variants", {1}}}});
  map(5, {{{"material", 2}, {"variants", {0}}}});
  std::filesystem::copy_file(asset("cornell_box.bin"), dir / "cornell_box.bin",
                             std::filesystem::copy_options::overwrite_existing);
  const std::filesystem::path path = dir / "cornell_variants.gltf";
  std::ofstream(path) << gltf.dump(2);
  return path;
}

}  // namespace hipr::test
