// save_scene: the source file's JSON, patched where the scene differs from what it loads as.
//
// Why patch the JSON (nlohmann::ordered_json) instead of re-serialising a tinygltf::Model: the
// model is lossy for a writer (tinygltf re-encodes decoded images, drops JSON it does not
// model, reorders keys, rewrites numbers), while every byte the edits did not touch must
// survive: meshes, accessors, samplers, unknown extensions and extras, key order, the numbers'
// own text. Patching also makes "unedited" easy to define: a value is rewritten only when the
// file does not already load as the scene's value (gltf_json_values.h), so an unedited scene
// saves as the same document. Buffers and images are carried as bytes, never decoded.
#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>

#include "core/error.h"
#include "hipr/scene_writer.h"
#include "scene/gltf_instance_writer.h"
#include "scene/gltf_light_writer.h"
#include "scene/gltf_material_writer.h"
#include "scene/gltf_mesh_writer.h"
#include "scene/gltf_node_writer.h"
#include "scene/gltf_output.h"
#include "scene/gltf_source.h"

namespace hipr {
namespace fs = std::filesystem;

namespace {

bool uses_extension(const gltf::Json& doc, const char* kind, const std::string& extension) {
  if (!doc.contains(kind) || !doc[kind].is_array()) return false;
  return std::any_of(doc[kind].begin(), doc[kind].end(), [&](const gltf::Json& item) {
    return item.is_object() && item.contains("extensions") && item["extensions"].is_object() &&
           item["extensions"].contains(extension);
  });
}

void declare_extension(gltf::Json& doc, const std::string& extension) {
  gltf::Json& used = gltf::array_member(doc, "extensionsUsed");
  if (std::find(used.begin(), used.end(), extension) == used.end()) used.push_back(extension);
}

// Lists in extensionsUsed the extensions the writer gave materials or nodes.
void declare_extensions(gltf::Json& doc) {
  std::vector<std::pair<const char*, std::string>> written;
  for (const std::string& e : gltf::material_extensions_written())
    written.push_back({"materials", e});
  written.push_back({"nodes", "KHR_node_visibility"});
  written.push_back({"nodes", "KHR_lights_punctual"});  // an imported lamp in a scene without one
  for (const auto& [kind, extension] : written) {
    if (uses_extension(doc, kind, extension)) declare_extension(doc, extension);
  }
}

}  // namespace

void save_scene(const Scene& scene, const fs::path& path) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return char(std::tolower(c)); });
  if (extension != ".gltf" && extension != ".glb")
    throw InputError(path.string() + ": cannot save as this format (expected .gltf or .glb)");
  const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(folder, ec))
    throw InputError("cannot save " + path.string() + ": folder does not exist");
  if (fs::is_directory(path, ec))
    throw InputError("cannot save " + path.string() + ": it is a folder");

  const gltf::SourceDocument source = gltf::read_source(scene.source);
  gltf::Json doc = source.json;
  try {
    gltf::BufferWriter buffer(doc);  // for what is written anew: meshes, imported images
    gltf::write_meshes(doc, scene, buffer,
                       source.name);  // before the imported materials are appended
    gltf::TextureWriter textures(doc, scene, buffer);
    const std::vector<Material> materials =
        gltf::write_new_materials(doc, scene.materials, textures);
    gltf::write_nodes(doc, scene, source.name);
    gltf::write_gpu_instances(doc, scene, buffer);
    gltf::write_lights(doc, scene.lights, source.name);
    gltf::write_materials(doc, materials, source.name);
    buffer.finish();
    if (textures.uses_transform()) declare_extension(doc, "KHR_texture_transform");
  } catch (const nlohmann::json::exception& e) {
    // The source was read again from disk: it may have been rewritten since it was loaded.
    throw InputError(source.name + ": its JSON no longer has the structure it was loaded with (" +
                     std::string(e.what()) + ")");
  }
  declare_extensions(doc);
  if (extension == ".glb")
    gltf::write_glb(source, std::move(doc), path);
  else
    gltf::write_gltf(source, std::move(doc), path);
}

}  // namespace hipr
