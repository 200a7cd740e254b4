#pragma once
// Checks made on a glTF document before tinygltf parses it (our code first: the JSON, its
// version, the extensions it requires, every URI), and which extensions hipr implements.
#include <string>
#include <vector>

namespace hipr::gltf {

// The JSON chunk of a .glb (its container already checked), or the whole .gltf file.
std::string json_text(const std::vector<unsigned char>& bytes, bool glb);
// Throws InputError naming `name` for invalid JSON, a glTF other than 2.x, a required extension
// hipr does not implement, a URI that leaves the scene's folder, or an image in a bufferView that
// is not wholly inside its buffer.
void precheck_json(const std::string& text, const std::string& name);
// One warning per optional extension the renderer does not implement (the file still renders).
void warn_unsupported_extensions(const std::vector<std::string>& used, const std::string& name);

}  // namespace hipr::gltf
