#include "fuzz_inputs.h"

#include <cstring>
#include <fstream>
#include <string>
#include <variant>
#include <vector>

#include "core/error.h"
#include "hipr/edits.h"
#include "hipr/scene_diff.h"
#include "hipr/scene_loader.h"
#include "image/builtin_environments.h"
#include "image/environment_loader.h"

namespace hipr::fuzz {
namespace {

std::filesystem::path write_alone(const uint8_t* data, size_t size, const std::filesystem::path& folder,
                                  const std::string& name) {
  std::filesystem::remove_all(folder);
  std::filesystem::create_directories(folder);
  const std::filesystem::path path = folder / name;
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

bool starts_with(const uint8_t* data, size_t size, const char* magic, size_t length) {
  return size >= length && std::memcmp(data, magic, length) == 0;
}

void apply_all(Scene scene, const std::vector<Edit>& edits) {
  for (const Edit& edit : edits) {
    if (const auto* e = std::get_if<EnvironmentEdit>(&edit))
      if (e->source && !is_environment_name(*e->source)) continue;
    try {
      const Scene before = scene;
      const Edit inverse = inverse_edit(scene, edit);
      apply_edit(scene, edit);
      (void)diff_scenes(before, scene);
      apply_edit(scene, inverse);
      (void)diff_scenes(before, scene);
      apply_edit(scene, edit);  // the next edit starts from this one
    } catch (const InputError&) {
    }
  }
}

}  // namespace

void load_gltf_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder) {
  const bool glb = starts_with(data, size, "glTF", 4);
  const std::filesystem::path path = write_alone(data, size, folder, glb ? "scene.glb" : "scene.gltf");
  try {
    const Scene scene = load_scene(path, {.environment = kNoEnvironment});
    (void)scene.instances();
    (void)scene.bounds();
  } catch (const InputError&) {
  }
}

void apply_edit_script_bytes(const uint8_t* data, size_t size, const std::filesystem::path& assets) {
  static const Scene cornell = load_scene(assets / "cornell_box.gltf", {.environment = kNoEnvironment});
  static const Scene furnace = load_scene(assets / "furnace_sphere.gltf", {.environment = "studio"});
  std::vector<Edit> edits;
  try {
    edits = parse_edit_script(std::string(reinterpret_cast<const char*>(data), size), "fuzz.json");
  } catch (const InputError&) {
    return;
  }
  apply_all(cornell, edits);
  apply_all(furnace, edits);
}

void load_environment_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder) {
  const bool exr = starts_with(data, size, "\x76\x2f\x31\x01", 4);
  const std::filesystem::path path = write_alone(data, size, folder, exr ? "map.exr" : "map.hdr");
  try {
    (void)load_environment(path);
  } catch (const InputError&) {
  }
}

}  // namespace hipr::fuzz
