#pragma once
// Checks a binary glTF container before any parser reads it: header, chunk lengths and bounds.
#include <cstdint>
#include <string>
#include <vector>

namespace hipr::gltf {

// Throws InputError naming the first problem (bad magic, version, length, truncated chunk).
void check_glb_container(const std::vector<unsigned char>& bytes, const std::string& name);

bool looks_like_glb(const std::vector<unsigned char>& bytes);

}  // namespace hipr::gltf
