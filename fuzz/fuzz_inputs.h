#pragma once
// What the fuzz targets feed hipr, shared with the regression tests
// (tests/fuzz_regression_test.cpp) so that every input the fuzzer ever found is replayed by the
// ordinary test suite. Each function takes untrusted bytes and must return normally: an input hipr
// refuses is an InputError (caught here); any other exception, a crash or a hang is a bug.
#include <cstddef>
#include <cstdint>
#include <filesystem>

namespace hipr::fuzz {

// The bytes as a glTF scene: .glb when they start with its magic, else .gltf JSON, in a folder
// of their own (`folder`, emptied first) so that references to other files find nothing. A scene
// that loads is then derived as the GPU scene's build derives it on the host (the software
// traversal's BVHs, the light tables, the camera), its invariants checked.
void load_gltf_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder);

// The bytes as an edit script, each edit applied (with its inverse, as undo does) to the
// shipped Cornell box and to a furnace scene with an environment, each edited scene derived as
// above. Environment files named by
// the script are not read (the fuzzer cannot make files; reading /dev paths could hang).
void apply_edit_script_bytes(const uint8_t* data, size_t size, const std::filesystem::path& assets);

// The bytes as an environment image: .exr when they start with OpenEXR's magic, else .hdr.
void load_environment_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder);

// The bytes as an image `hipr compare` reads (OpenEXR, PNG or Radiance, told apart by content),
// then compared with itself and with a copy one texel off in every metric, as a screenshot
// regression suite's files are.
void read_image_bytes(const uint8_t* data, size_t size, const std::filesystem::path& folder);

}  // namespace hipr::fuzz
