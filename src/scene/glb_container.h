#pragma once
// Checks a binary glTF container before any parser reads it: header, chunk lengths and bounds.
#include <cstdint>
#include <string>
#include <vector>

namespace hipr::gltf {

// Throws InputError naming the first problem (bad magic, version, length, truncated chunk).
void check_glb_container(const std::vector<unsigned char>& bytes, const std::string& name);

bool looks_like_glb(const std::vector<unsigned char>& bytes);

// The same container (checked already) with its JSON chunk replaced by `json`; the chunks after
// it are kept byte for byte.
std::vector<unsigned char> glb_with_json(const std::vector<unsigned char>& bytes,
                                         const std::string& json);

}  // namespace hipr::gltf
