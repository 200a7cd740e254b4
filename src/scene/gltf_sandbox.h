#pragma once
// Confines every file a glTF scene reads to the scene's own folder. Untrusted scenes may name
// any URI; only data: URIs and relative paths that stay inside the folder are read.
#include <filesystem>
#include <string>
#include <vector>

#include "core/hash.h"

namespace hipr::gltf {

// Throws InputError when `uri` is absolute, has a scheme other than data:, or leaves the
// folder through "..". `what` names the referencing object ("buffer 0") for the message.
void check_uri(const std::string& uri, const std::string& what);

// Percent-decodes a URI reference (glTF URIs are RFC 3986 encoded).
std::string decode_uri(const std::string& uri);

// Reads files for tinygltf; every read is checked to resolve (after symlinks) inside `root`,
// and its bytes feed the scene's content hash.
class Sandbox {
 public:
  explicit Sandbox(const std::filesystem::path& root);
  bool read(std::vector<unsigned char>* out, std::string* err, const std::string& path);
  bool exists(const std::string& path) const;
  Hasher& hasher() { return m_hasher; }

 private:
  bool inside(const std::filesystem::path& path) const;
  std::filesystem::path m_root;
  Hasher m_hasher;
};

}  // namespace hipr::gltf
