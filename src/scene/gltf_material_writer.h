#pragma once
// Scene materials -> glTF material JSON: the inverse of gltf_material_table.cpp, with
// extras.hipr_openpbr (gltf_hipr_extras.h) for every value glTF cannot hold.
#include <string>
#include <vector>

#include "hipr/scene.h"
#include "scene/gltf_json_values.h"
#include "scene/gltf_texture_writer.h"

namespace hipr::gltf {

// Rewrites doc["materials"] (and the document's extras for glTF's default material) so that
// loading `doc` gives the parameters of `materials`: the scene's, one per glTF material, then
// glTF's default material. Only values that differ from what the file already loads as are
// rewritten. `name` names the file in messages.
void write_materials(Json& doc, const std::vector<Material>& materials, const std::string& name);

// Materials an import brought (the scene's beyond the file's and glTF's default, which comes
// right after the file's): appended to doc["materials"] as stubs holding what write_materials
// does not write (name, alphaMode and cutoff, doubleSided, a volume's thickness, the texture
// references, written through `textures`). Returns the scene's materials in the order
// write_materials then wants: the file's, the appended ones, glTF's default.
std::vector<Material> write_new_materials(Json& doc, const std::vector<Material>& materials,
                                          TextureWriter& textures);

// The glTF extensions write_materials may add to a material (for extensionsUsed).
std::vector<std::string> material_extensions_written();

}  // namespace hipr::gltf
