#pragma once
// Shader sources compiled into the binary by cmake/embed_shaders.cmake.
#include <string_view>
#include <vector>

namespace hipr::vk {

struct EmbeddedShaderFile {
  std::string_view path;  // relative to shaders/, e.g. "shared/abi.h"
  std::string_view text;
};

const std::vector<EmbeddedShaderFile>& embedded_shader_files();

}  // namespace hipr::vk
