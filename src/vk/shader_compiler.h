#pragma once
// GLSL -> SPIR-V through the glslang library, at run time, so kernels can be specialized per
// scene with #defines. Results are cached on disk, keyed by every shader source + the defines.
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace hipr::vk {

using ShaderDefines = std::vector<std::pair<std::string, std::string>>;

struct CompiledShader {
  std::vector<uint32_t> spirv;
  bool from_cache = false;
};

// `entry` is a path relative to shaders/ (e.g. "trace_tiles.comp").
// Cache folder: $HIPR_CACHE_DIR, else $XDG_CACHE_HOME/hipr, else ~/.cache/hipr; no cache when
// none is writable.
CompiledShader compile_compute_shader(const std::string& entry, const ShaderDefines& defines);

std::filesystem::path shader_cache_dir();

}  // namespace hipr::vk
