#pragma once
// The file a scene was loaded from, reread for the writer: its JSON (key order kept), the GLB
// binary chunk, and the bytes its URIs name, read under the loader's sandbox rules.
#include <filesystem>
#include <string>
#include <vector>

#include "scene/gltf_json_values.h"

namespace hipr::gltf {

struct SourceDocument {
  std::filesystem::path path;
  std::filesystem::path folder;  // absolute: what its relative URIs resolve against
  std::string name;              // file name, for messages
  bool glb = false;
  Json json;
  std::vector<unsigned char> bin;  // the GLB BIN chunk (empty for .gltf)
};

// Throws InputError when the file cannot be read or is not glTF.
SourceDocument read_source(const std::filesystem::path& path);

bool is_data_uri(const std::string& uri);

// The bytes `uri` names: a decoded data: URI, or a file inside the source folder. `what` names
// the referencing object ("image 2") in the InputError thrown when it cannot be read.
std::vector<unsigned char> read_uri(const SourceDocument& source, const std::string& uri,
                                    const std::string& what);

// The file inside the source folder a non-data URI names, relative to the folder (decoded).
std::filesystem::path uri_path(const std::string& uri, const std::string& what);

// Every file (non-data) URI of the source's buffers and images, with "buffer N"/"image N".
struct SideFile {
  std::string uri;
  std::string what;
};
std::vector<SideFile> side_files(const Json& doc);

}  // namespace hipr::gltf
