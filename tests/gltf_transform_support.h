#pragma once
// glTF-Transform (the npm package @gltf-transform/cli in tools/node_modules, installed by
// tools/setup-deps.sh): the compressed and optimized copies the loader's tests read.
#include <filesystem>
#include <string>

namespace hipr::test {

// Whether node runs it here.
bool gltf_transform_available();

// `gltf-transform COMMAND input output ARGUMENTS`; a test failure when it fails. Returns output.
std::filesystem::path gltf_transform(const std::string& command, const std::filesystem::path& input,
                                     const std::filesystem::path& output,
                                     const std::string& arguments = "");

}  // namespace hipr::test

// Skips the test without glTF-Transform, or fails it where the set-up says it installed it
// (HIPR_REQUIRE_GLTF_VALIDATOR=1: the same npm install brings both node tools).
#define HIPR_REQUIRE_GLTF_TRANSFORM()                                                  \
  do {                                                                                 \
    if (!::hipr::test::gltf_transform_available()) {                                   \
      if (::hipr::test::gltf_validator_required())                                     \
        FAIL() << "glTF-Transform is not installed (tools/setup-deps.sh installs it)"; \
      GTEST_SKIP() << "glTF-Transform is not installed (npm ci --prefix tools)";       \
    }                                                                                  \
  } while (0)
